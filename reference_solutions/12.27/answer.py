"""Problem 12.27: particle on the inside of a smooth cone, vertex down at O, half-angle alpha.

On the surface rho = z tan(alpha): v^2 = rho'^2 + rho^2 phi'^2 + z'^2 = z'^2/cos^2(alpha) + z^2 tan^2(alpha) phi'^2.
L = m/2 (z'^2 sec^2 + z^2 tan^2 phi'^2) - m g z
z:   m z''/cos^2(alpha) = m z tan^2(alpha) phi'^2 - m g
phi: d/dt(m z^2 tan^2(alpha) phi') = 0
Circle z = h: h tan^2(alpha) omega^2 = g  ->  omega = sqrt(g/h) cot(alpha).
"""
from sympy import Eq, Function, cos, sqrt, symbols, tan

t = symbols("t")
m, g, h, alpha = symbols("m g h alpha", positive=True)
z, phi = Function("z")(t), Function("phi")(t)
zd, phid = z.diff(t), phi.diff(t)

L = m / 2 * (zd**2 / cos(alpha) ** 2 + z**2 * tan(alpha) ** 2 * phid**2) - m * g * z
eom = [
    Eq(m * z.diff(t, 2) / cos(alpha) ** 2, m * z * tan(alpha) ** 2 * phid**2 - m * g),
    Eq((m * z**2 * tan(alpha) ** 2 * phid).diff(t), 0),
]
omega = sqrt(g / h) / tan(alpha)
# relative equilibrium: the z equation with z' = z'' = 0 gives z*tan(alpha)**2*phi'**2 = g
equilibrium = {"z": g / (tan(alpha) ** 2 * phid**2)}
