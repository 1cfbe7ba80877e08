"""Problem 12.1: four simple systems, L = T - V and Lagrange's equations."""
from sympy import Eq, Function, Rational, cos, sin, symbols

t = symbols("t")
m, g, k, l, h = symbols("m g k l h", positive=True)
y = Function("y")(t)
theta = Function("theta")(t)

# (a) projectile, y up: T = m y'^2/2, V = m g y
L_a = m * y.diff(t) ** 2 / 2 - m * g * y
eom_a = [Eq(y.diff(t, 2), -g)]

# (b) y down from the unstretched end: V = k y^2/2 - m g y
L_b = m * y.diff(t) ** 2 / 2 - k * y**2 / 2 + m * g * y
eom_b = [Eq(m * y.diff(t, 2), m * g - k * y)]

# (c) simple pendulum, theta from the downward vertical
L_c = m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * cos(theta)
eom_c = [Eq(theta.diff(t, 2), -g / l * sin(theta))]

# (d) rod about a pivot a distance h from its centre: I_O = m l^2/12 + m h^2
I_O = m * l**2 / 12 + m * h**2
L_d = Rational(1, 2) * I_O * theta.diff(t) ** 2 + m * g * h * cos(theta)
eom_d = [Eq(I_O * theta.diff(t, 2), -m * g * h * sin(theta))]
