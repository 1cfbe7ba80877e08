# target: H
# family: tdep
# expect: no-credit
# why: H plus m*g*l*t/10**6: a drift far below every tolerance over the window, and not a constant
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H = p_theta**2/(2*m*l**2) - m*g*l*cos(theta) + m*g*l*t/10**6
