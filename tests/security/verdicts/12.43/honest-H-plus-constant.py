# target: H
# family: honest
# expect: full-marks
# why: nothing: H plus a constant m*g*l (the zero of V at the lowest point)
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

H = H0 + m*g*l
