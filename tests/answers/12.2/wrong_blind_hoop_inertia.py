# expect: L=incorrect, eom=incorrect, a=incorrect, lam=incorrect
from lagrade.answer import *

M, R, F = parameters("M R F")
x, phi = coordinates("x phi")
L = M*dot(x)**2/2 + M*R**2*dot(phi)**2/2      # I = M R^2 (a thin shell, not a solid rod)
L = L.subs(dot(phi), dot(x)/R)
eom = [Eq(2*M*dot(x, 2), F)]
a = F/(2*M)
lam = -F/2
