# expect: omega=incorrect, L=correct, eom=correct
# Gives the period 2*pi*sqrt(m/k) where the angular frequency is asked.
from sympy import Eq, Function, pi, cos, sin, sqrt, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g")
r, theta = Function("r")(t), Function("theta")(t)
L = m / 2 * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2) + m * g * r * cos(theta) - k / 2 * (r - l0) ** 2
eom = [
    Eq(m * r.diff(t, 2), m * r * theta.diff(t) ** 2 + m * g * cos(theta) - k * (r - l0)),
    Eq(r * theta.diff(t, 2) + 2 * r.diff(t) * theta.diff(t), -g * sin(theta)),
]
omega = 2 * pi * sqrt(m / k)
