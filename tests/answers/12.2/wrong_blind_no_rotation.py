# expect: L=incorrect, eom=incorrect, a=incorrect, lam=incorrect
from lagrade.answer import *

M, R, F = parameters("M R F")
x, phi = coordinates("x phi")
L = M*dot(x)**2/2
eom = [Eq(M*dot(x, 2), F)]
a = F/M
lam = 0*F
