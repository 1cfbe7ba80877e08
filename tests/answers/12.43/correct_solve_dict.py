# expect: eom=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)

H = p_theta**2 / (2 * m * l**2) - m * g * l * cos(theta)
hamilton = [
    Eq(theta.diff(t), H.diff(p_theta)),
    Eq(p_theta.diff(t), -H.diff(theta)),
]
# theta'' = p_theta'/(m l^2) = -(g/l) sin(theta)
eom = Eq(theta.diff(t, 2), -g / l * sin(theta))

# ---- the form under test
from sympy import Eq, Function, sin, solve, symbols

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta = Function("theta")(t)
eom = solve(Eq(m * l**2 * theta.diff(t, 2), -m * g * l * sin(theta)), theta.diff(t, 2), dict=True)
