# target: H
# family: honest
# expect: full-marks
# why: nothing: (exp(I*theta) + exp(-I*theta))/2 is cos(theta)
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

H = p_theta**2/(2*m*l**2) - m*g*l*(exp(I*theta) + exp(-I*theta))/2
