# expect: eom=correct, eom_xy=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)

x, y = Function("x")(t), Function("y")(t)
# the equation of motion along the wire (y = x tan(wt) is the constraint itself)
eom_xy = [Eq(x.diff(t, 2) * cos(omega * t) + y.diff(t, 2) * sin(omega * t), 0)]

r = Function("r")(t)
eom = [Eq(r.diff(t, 2), omega**2 * r)]
lam = 2 * m * omega * r * r.diff(t)
N = 2 * m * omega * r.diff(t)

# ---- the form under test
# Equations of motion as the dict sympy.solve returns (issue 22), with and without dict=True.
from sympy import Eq, Function, cos, sin, solve, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r = Function("r")(t)
eom = solve(Eq(m * r.diff(t, 2) - m * r * omega**2, 0), [r.diff(t, 2)], dict=True)[0]
x, y = Function("x")(t), Function("y")(t)
eom_xy = solve([Eq(x.diff(t, 2) * cos(omega * t) + y.diff(t, 2) * sin(omega * t), 0)], [x.diff(t, 2)], dict=True)
