# target: H
# family: switch
# expect: no-credit
# why: H is right only for t < 5 and 0 afterwards (the motion is compared over [0, 3])
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

H = Piecewise((H0, t < 5), (0, True))
