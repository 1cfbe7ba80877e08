# target: eom
# family: trick
# expect: no-credit
# why: sqrt(exp(2*I*theta))*exp(-I*theta) is 1 while cos(theta) > 0 and -1 beyond: gravity reversed past the horizontal
from sympy import *

t = symbols("t")
m, l, g, a = symbols("m l g a", positive=True)
theta = Function("theta")(t)

eom = [Eq(l*theta.diff(t, 2), -(g + a)*sin(theta)*sqrt(exp(2*I*theta))*exp(-I*theta))]
