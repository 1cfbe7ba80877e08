# target: H
# family: complex
# expect: no-credit
# why: H has an imaginary part 1000*I*p_theta*theta
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

H = H0 + 1000*I*p_theta*theta
