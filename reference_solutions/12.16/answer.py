"""Problem 12.16: spherical pendulum, theta from the downward vertical."""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, R, g = symbols("m R g", positive=True)
theta, phi = Function("theta")(t), Function("phi")(t)
thd, phd = theta.diff(t), phi.diff(t)

L = m * R**2 / 2 * (thd**2 + sin(theta) ** 2 * phd**2) + m * g * R * cos(theta)
eom = [
    Eq(theta.diff(t, 2), sin(theta) * cos(theta) * phd**2 - g / R * sin(theta)),
    Eq((m * R**2 * sin(theta) ** 2 * phd).diff(t), 0),
]
p_phi = m * R**2 * sin(theta) ** 2 * phd
E = m * R**2 / 2 * (thd**2 + sin(theta) ** 2 * phd**2) - m * g * R * cos(theta)
conserved = [p_phi, E]
