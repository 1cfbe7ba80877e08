# L in phi with a total time derivative d/dt(M*R*phi*t) added; eom solved for phi''; unevaluated forms.
from sympy import Eq, Function, symbols

t = symbols("t")
M, R, F = symbols("M R F")
phi = Function("phi")(t)
L = 3 * M * R**2 * phi.diff(t) ** 2 / 4 + M * R * (phi + t * phi.diff(t))
eom = Eq(phi.diff(t, 2), 2 * F / (3 * M * R))
a = F * 2 / M / 3
lam = Eq(symbols("f"), -F + M * a)
