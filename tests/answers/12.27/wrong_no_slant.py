# expect: L=incorrect, eom=partial, omega=correct, equilibrium=correct
# L and eom are extras (the book asks only omega): wrong, shown, not counted in the score (issue 33).
# Forgot that rho = z*tan(alpha) changes with z: T has z'**2 instead of z'**2/cos(alpha)**2
# (the phi equation survives; the circle condition does not depend on it).
from lagrade.answer import *

m, g, h, alpha = parameters("m g h alpha")
z, phi = coordinates("z phi")
L = m / 2 * (dot(z) ** 2 + z**2 * tan(alpha) ** 2 * dot(phi) ** 2) - m * g * z
eom = [Eq(dot(z, 2), z * tan(alpha) ** 2 * dot(phi) ** 2 - g), Eq(z * dot(phi, 2) + 2 * dot(z) * dot(phi), 0)]
omega = sqrt(g / h) / tan(alpha)
equilibrium = {"z": h, "phi_d": sqrt(g / h) / tan(alpha)}
