# expect: L=partial, eom=correct
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m*(dot(x1)**2 + dot(x2)**2) - k*x1**2 - k*(x2 - x1)**2      # 2*L: same motion, wrong momenta
eom = [Eq(m*dot(x1, 2), -2*k*x1 + k*x2), Eq(m*dot(x2, 2), k*x1 - k*x2)]
