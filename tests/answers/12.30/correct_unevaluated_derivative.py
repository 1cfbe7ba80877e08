# expect: eom=correct, N=correct
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
# The torque written as the rate of change of the angular momentum, left unevaluated (issue 22).
from sympy import Derivative, Eq, Function, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r = Function("r")(t)
eom = [Eq(r.diff(t, 2), omega**2 * r)]
lam = Derivative(m * r**2 * omega, t)
N = Derivative(m * r**2 * omega, t) / r
