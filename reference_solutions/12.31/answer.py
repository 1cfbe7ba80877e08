"""Problem 12.31: bead on the helix r = a, z = k theta, attracted to the origin by F = -c r_vec.

v^2 = r'^2 + r^2 theta'^2 + z'^2 = (a^2 + k^2) theta'^2, V = c (r^2 + z^2)/2 = c (a^2 + k^2 theta^2)/2.
L = m (a^2 + k^2) theta'^2/2 - c (a^2 + k^2 theta^2)/2
m (a^2 + k^2) theta'' = -c k^2 theta: simple harmonic about theta = 0, w = k sqrt(c/(m (a^2 + k^2))).
"""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, a, k, c, theta0, thetadot0 = symbols("m a k c theta0 thetadot0", positive=True)
theta = Function("theta")(t)

L = m * (a**2 + k**2) * theta.diff(t) ** 2 / 2 - c * (a**2 + k**2 * theta**2) / 2
eom = [Eq(m * (a**2 + k**2) * theta.diff(t, 2), -c * k**2 * theta)]
omega = k * sqrt(c / (m * (a**2 + k**2)))
solution = {"theta": theta0 * cos(omega * t) + thetadot0 / omega * sin(omega * t)}
