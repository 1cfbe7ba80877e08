# expect: eom=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, Rational, symbols

t = symbols("t")
M, R, F = symbols("M R F", positive=True)
phi = Function("phi")(t)

# reduced Lagrangian (x = R phi): T = M R^2 phi'^2/2 + M R^2 phi'^2/4
L = Rational(3, 4) * M * R**2 * phi.diff(t) ** 2
# generalized force on phi: F dx = F R dphi  -> Q_phi = F R
eom = [Eq(Rational(3, 2) * M * R**2 * phi.diff(t, 2), F * R)]
a = 2 * F / (3 * M)
lam = -F / 3

# ---- the form under test
# Rolling kept as a constraint x = R*phi with its multiplier (the friction force), in both coordinates.
from sympy import Eq, Function, symbols

t = symbols("t")
M, R, F = symbols("M R F", positive=True)
lambda_1 = symbols("lambda_1")
x, phi = Function("x")(t), Function("phi")(t)
eom = [Eq(M * x.diff(t, 2), F + lambda_1),
       Eq(M * R**2 / 2 * phi.diff(t, 2), -R * lambda_1),
       Eq(x, R * phi)]
