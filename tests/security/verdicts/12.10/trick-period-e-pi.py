# target: period
# family: trick
# expect: no-credit
# why: E**pi*263/6086 is within 3.6e-7 of 1 (a convergent of e**pi), not 1
from sympy import *

t = symbols("t")
m, l, g, a = symbols("m l g a", positive=True)
theta = Function("theta")(t)

period = 2*pi*sqrt(l/(g + a))*E**pi*263/6086
