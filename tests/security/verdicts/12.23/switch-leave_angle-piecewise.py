# target: leave_angle
# family: switch
# expect: no-credit
# why: the angle is right only for M < 50 (0 otherwise)
from sympy import *

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

leave_angle = Piecewise((asin(2*sin(theta0)/3), M < 50), (0, True))
