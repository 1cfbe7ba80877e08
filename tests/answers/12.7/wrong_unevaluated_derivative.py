# expect: eom=partial
# The angular momentum differentiated as if r were constant would be wrong; here the
# unevaluated derivative is of the wrong quantity (m*r*theta' instead of m*r**2*theta').
from sympy import Derivative, Eq, Function, cos, sin, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
eom = [
    Eq(Derivative(m * r.diff(t), t), m * r * theta.diff(t) ** 2 + m * g * cos(theta) - k * (r - l0)),
    Eq(Derivative(m * r * theta.diff(t), t), -m * g * r * sin(theta)),
]
