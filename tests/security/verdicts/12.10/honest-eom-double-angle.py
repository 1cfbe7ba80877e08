# target: eom
# family: honest
# expect: full-marks
# why: nothing: sin(theta) written as 2 sin(theta/2) cos(theta/2)
from sympy import *

t = symbols("t")
m, l, g, a = symbols("m l g a", positive=True)
theta = Function("theta")(t)

eom = [Eq(l*theta.diff(t, 2), -(g + a)*2*sin(theta/2)*cos(theta/2))]
