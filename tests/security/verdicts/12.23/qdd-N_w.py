# target: N_w
# family: qdd
# expect: no-credit
# why: the wall force is M x_cm'' left with theta'' in it: the equation of motion was never used
from sympy import *

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

N_w = M*(l*cos(theta)/2).diff(t, 2)
