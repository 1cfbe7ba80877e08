# expect: L=correct, eom=correct, a=correct, lam=incorrect
# Friction taken along F: the sign of the multiplier is wrong.
from lagrade.answer import *

M, R, F = parameters("M R F")
phi = coordinates("phi")
L = Rational(3, 4) * M * R**2 * phi.diff(t) ** 2
eom = [Eq(phi.diff(t, 2), 2 * F / (3 * M * R))]
a = 2 * F / (3 * M)
lam = F / 3
