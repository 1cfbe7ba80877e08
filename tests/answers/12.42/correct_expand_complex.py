# expect: solution=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x0, v0 = symbols("x0 v0")
x = Function("x")(t)
p_x = Function("p_x")(t)

H = p_x**2 / (2 * m) + k * x**2 / 2
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -k * x)]
omega = sqrt(k / m)
solution = {"x": x0 * cos(omega * t) + v0 / omega * sin(omega * t)}

# ---- the form under test
from sympy import I, exp, expand, sqrt, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x0, v0 = symbols("x0 v0")
w = sqrt(k / m)
A = (x0 - I * v0 / w) / 2
solution = {"x": expand(A * exp(I * w * t) + A.conjugate() * exp(-I * w * t), complex=True)}
