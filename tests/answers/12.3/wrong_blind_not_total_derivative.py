# expect: L=incorrect, eom=correct
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m*(dot(x1)**2 + dot(x2)**2)/2 - k*x1**2/2 - k*(x2 - x1)**2/2 + k*dot(x1)*x2   # not a total derivative
eom = [Eq(m*dot(x1, 2) + 2*k*x1 - k*x2, 0), Eq(m*dot(x2, 2) - k*x1 + k*x2, 0)]
