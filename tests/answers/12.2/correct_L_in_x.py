# The reduced Lagrangian written in x instead of phi (x = R*phi): the same physics, must be correct.
from lagrade.answer import *

M, R, F = parameters("M R F")
x = coordinates("x")
L = Rational(3, 4) * M * x.diff(t) ** 2
eom = [Eq(Rational(3, 2) * M * x.diff(t, 2), F)]
a = 2 * F / (3 * M)
lam = -F / 3
