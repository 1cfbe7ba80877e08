# expect: omega=incorrect, L=correct, eom=correct, equilibrium=incorrect
# The circle condition solved with tan(alpha) upside down.
from lagrade.answer import *

m, g, h, alpha = parameters("m g h alpha")
z, phi = coordinates("z phi")
L = m / 2 * (dot(z) ** 2 / cos(alpha) ** 2 + z**2 * tan(alpha) ** 2 * dot(phi) ** 2) - m * g * z
eom = [Eq(dot(z, 2), cos(alpha) ** 2 * (z * tan(alpha) ** 2 * dot(phi) ** 2 - g)), Eq(z * dot(phi, 2) + 2 * dot(z) * dot(phi), 0)]
omega = sqrt(g / h) * tan(alpha)
equilibrium = {"z": g * tan(alpha) ** 2 / dot(phi) ** 2}
