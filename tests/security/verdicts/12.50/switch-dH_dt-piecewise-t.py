# target: dH_dt
# family: switch
# expect: no-credit
# why: dH/dt is right only for t < 3 and 0 afterwards
from sympy import *

t = symbols("t")
m, k, tau = symbols("m k tau", positive=True)
x = Function("x")(t)

dH_dt = Piecewise((-k*exp(-t/tau)/(tau*x), t < 3), (0, True))
