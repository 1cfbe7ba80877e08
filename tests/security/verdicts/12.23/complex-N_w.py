# target: N_w
# family: complex
# expect: no-credit
# why: the wall force has an imaginary part 1000*I*M*g
from sympy import *

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

N_w = M*cos(theta)*(3*g*sin(theta)/4 - l*thd**2/2) + 1000*I*M*g
