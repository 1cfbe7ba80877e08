# expect: L_d=incorrect, eom_d=incorrect, L_c=correct, eom_c=correct
# (d) takes I = m*l**2/3 (about the end of the rod), but the pivot is a distance h from the centre.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, g, k, l, h = symbols("m g k l h")
y, theta = Function("y")(t), Function("theta")(t)

L_a = m * y.diff(t) ** 2 / 2 - m * g * y
eom_a = [Eq(y.diff(t, 2), -g)]
L_b = m * y.diff(t) ** 2 / 2 - k * y**2 / 2 + m * g * y
eom_b = [Eq(m * y.diff(t, 2), m * g - k * y)]
L_c = m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * cos(theta)
eom_c = [Eq(theta.diff(t, 2), -g / l * sin(theta))]
L_d = m * l**2 * theta.diff(t) ** 2 / 6 + m * g * h * cos(theta)
eom_d = [Eq(m * l**2 / 3 * theta.diff(t, 2), -m * g * h * sin(theta))]
