# L built from Cartesian coordinates of the particle (not simplified); eom solved for the accelerations;
# omega written with cot.
from lagrade.answer import *

m, g, h, alpha = parameters("m g h alpha")
z, phi = coordinates("z phi")
rho = z * tan(alpha)
X, Y = rho * cos(phi), rho * sin(phi)
L = m / 2 * (diff(X, t) ** 2 + diff(Y, t) ** 2 + diff(z, t) ** 2) - m * g * z
eom = [
    Eq(dot(phi, 2), -2 * dot(z) * dot(phi) / z),
    Eq(dot(z, 2), cos(alpha) ** 2 * (z * tan(alpha) ** 2 * dot(phi) ** 2 - g)),
]
omega = sqrt(g / h) * cot(alpha)
equilibrium = {"z": g / (tan(alpha) ** 2 * dot(phi) ** 2)}  # z equation with z' = z'' = 0
