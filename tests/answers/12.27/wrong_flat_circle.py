# expect: omega=incorrect, L=incorrect, eom=partial
# Treated it like a conical pendulum with gravity along the surface and the radius z*cot(alpha):
# wrong radius in T, and omega = sqrt(g/rho) with rho = h*tan(alpha).
from lagrade.answer import *

m, g, h, alpha = parameters("m g h alpha")
z, phi = coordinates("z phi")
L = m / 2 * (dot(z) ** 2 / cos(alpha) ** 2 + z**2 * cot(alpha) ** 2 * dot(phi) ** 2) - m * g * z
eom = [Eq(dot(z, 2), cos(alpha) ** 2 * (z * cot(alpha) ** 2 * dot(phi) ** 2 - g)), Eq(z * dot(phi, 2) + 2 * dot(z) * dot(phi), 0)]
omega = sqrt(g / (h * tan(alpha)))
