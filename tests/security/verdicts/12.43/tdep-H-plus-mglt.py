# target: H
# family: tdep
# expect: no-credit
# why: H + m*g*l*t: the same Hamilton's equations, but the value of H is not the energy up to a constant
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

H = H0 + m*g*l*t
