# target: eom
# family: roots
# expect: no-credit
# why: the product also allows theta'' = 7 g/l
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

eom = Eq((theta.diff(t, 2) + g/l*sin(theta))*(theta.diff(t, 2) - 7*g/l), 0)
