"""Problem 12.2: solid cylinder rolling without slipping, pushed by a horizontal force F at its axis.

T = M x'^2/2 + (M R^2/2) phi'^2/2 with the constraint f = x - R phi = 0 and Q_x = F.
Lagrange with a multiplier:  M x'' = F + lam,  (M R^2/2) phi'' = -R lam,  x'' = R phi''.
=> M R phi''/2 = -lam and M R phi'' = F + lam  => (3/2) M R phi'' = F  => x'' = 2F/(3M), lam = -F/3.
"""
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
