# expect: L=incorrect, eom=incorrect, a=incorrect, lam=incorrect
# Rotational kinetic energy forgotten: the cylinder treated as sliding.
from lagrade.answer import *

M, R, F = parameters("M R F")
phi = coordinates("phi")
L = M * R**2 * phi.diff(t) ** 2 / 2
eom = [Eq(M * R * phi.diff(t, 2), F)]
a = F / M
lam = 0
