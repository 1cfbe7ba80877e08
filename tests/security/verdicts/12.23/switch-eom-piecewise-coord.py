# target: eom
# family: switch
# expect: no-credit
# why: the equation is right only while theta < 50 (theta'' = 0 beyond)
from sympy import *

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

eom = [Eq(theta.diff(t, 2), Piecewise((-3*g*cos(theta)/(2*l), theta < 50), (0, True)))]
