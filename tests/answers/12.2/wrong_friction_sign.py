# expect: L=correct, eom=correct, a=correct, lam=incorrect
# lam: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# Friction taken along F: the sign of the multiplier is wrong.
from lagrade.answer import *

M, R, F = parameters("M R F")
phi = coordinates("phi")
L = Rational(3, 4) * M * R**2 * phi.diff(t) ** 2
eom = [Eq(phi.diff(t, 2), 2 * F / (3 * M * R))]
a = 2 * F / (3 * M)
lam = F / 3
