# target: leave_angle
# family: roots
# expect: no-credit
# why: the equation has a second root sin(theta) = sin(theta0)/7, an angle the ladder passes through
from sympy import *

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

leave_angle = Eq((3*sin(theta) - 2*sin(theta0))*(7*sin(theta) - sin(theta0)), 0)
