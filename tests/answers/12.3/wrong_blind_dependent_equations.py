# expect: L=correct
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m*(dot(x1)**2 + dot(x2)**2)/2 - k*x1**2/2 - k*(x2 - x1)**2/2
e1 = m*dot(x1, 2) + 2*k*x1 - k*x2
eom = [e1, 2*e1]          # the same equation twice: x2'' is left undetermined
