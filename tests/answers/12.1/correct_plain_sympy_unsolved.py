# Plain sympy, positive symbols, equations in unsolved Eq form with all terms on one side or scaled.
from sympy import Eq, Function, Symbol, cos, sin, symbols

t = Symbol("t")
m, g, k, l, h = symbols("m g k l h", positive=True)
y = Function("y")(t)
theta = Function("theta")(t)

L_a = m * y.diff(t) ** 2 / 2 - m * g * y + m * g * t * y.diff(t) + m * g * y   # + d/dt(m g t y)
eom_a = [Eq(m * y.diff(t, 2) + m * g, 0)]

L_b = (m * y.diff(t) ** 2 - k * y**2) / 2 + m * g * y
eom_b = [Eq(-m * y.diff(t, 2), k * y - m * g)]

L_c = m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * cos(theta) - m * g * l
eom_c = [Eq(m * l**2 * theta.diff(t, 2), -m * g * l * sin(theta))]

L_d = m * (l**2 / 12 + h**2) * theta.diff(t) ** 2 / 2 + m * g * h * cos(theta)
eom_d = [Eq(theta.diff(t, 2), -12 * g * h * sin(theta) / (l**2 + 12 * h**2))]
