"""Problem 12.45: bead on the helix r = a, z = k theta, under gravity (z up).

v^2 = r'^2 + r^2 theta'^2 + z'^2 = (a^2 + k^2) theta'^2;  V = m g z = m g k theta.
L = m (a^2 + k^2) theta'^2/2 - m g k theta, p_theta = m (a^2 + k^2) theta',
H = p_theta^2/(2 m (a^2 + k^2)) + m g k theta.
theta' = p_theta/(m (a^2 + k^2)), p_theta' = -m g k  (so z'' = k theta'' = -g k^2/(a^2 + k^2)).
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, a, k, g = symbols("m a k g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)

I = m * (a**2 + k**2)
H = p_theta**2 / (2 * I) + m * g * k * theta
hamilton = [Eq(theta.diff(t), p_theta / I), Eq(p_theta.diff(t), -m * g * k)]
