"""Problem 12.38: Hamilton's equations of the spring pendulum (Problem 12.7).

L = m (r'^2 + r^2 theta'^2)/2 + m g r cos(theta) - k (r - l0)^2/2; p_r = m r', p_theta = m r^2 theta';
H = p_r^2/(2m) + p_theta^2/(2 m r^2) - m g r cos(theta) + k (r - l0)^2/2 (= E: no t, T quadratic).
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
p_r, p_theta = Function("p_r")(t), Function("p_theta")(t)

H = p_r**2 / (2 * m) + p_theta**2 / (2 * m * r**2) - m * g * r * cos(theta) + k * (r - l0) ** 2 / 2
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(theta.diff(t), p_theta / (m * r**2)),
    Eq(p_r.diff(t), p_theta**2 / (m * r**3) + m * g * cos(theta) - k * (r - l0)),
    Eq(p_theta.diff(t), -m * g * r * sin(theta)),
]
