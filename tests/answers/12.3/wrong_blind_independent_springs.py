# expect: L=incorrect, eom=incorrect
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m*dot(x1)**2/2 + m*dot(x2)**2/2 - k*x1**2/2 - k*x2**2/2
eom = [Eq(m*dot(x1, 2), -k*x1), Eq(m*dot(x2, 2), -k*x2)]
