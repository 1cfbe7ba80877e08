# expect: eom_xy=correct, eom=correct
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
# Lagrange's equations with the multipliers kept, and the constraints beside them (issue 22):
# Cartesian with lam, polar with the multiplier mu written as a function of time.
from sympy import Derivative, Eq, Function, cos, sin, symbols, tan

t = symbols("t")
m, omega = symbols("m omega", positive=True)
x, y = Function("x")(t), Function("y")(t)
lam = symbols("lam")
eom_xy = [Eq(m * x.diff(t, 2), lam * sin(omega * t)),
          Eq(m * y.diff(t, 2), -lam * cos(omega * t)),
          Eq(x * sin(omega * t) - y * cos(omega * t), 0)]
r, theta = Function("r")(t), Function("theta")(t)
mu = Function("mu")(t)
eom = [m * r.diff(t, 2) - m * r * theta.diff(t) ** 2,
       Eq(Derivative(m * r**2 * theta.diff(t), t), mu),
       Eq(theta, omega * t)]
# the multiplier of the polar form, as the part asks (the symbol lam above was only a name)
lam = 2 * m * omega * r * r.diff(t)
