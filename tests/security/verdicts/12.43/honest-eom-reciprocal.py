# target: eom
# family: honest
# expect: full-marks
# why: nothing: 1/theta'' = 1/(-g sin(theta)/l) holds exactly where theta'' = -g sin(theta)/l (both nonzero)
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

eom = Eq(1/theta.diff(t, 2), 1/(-g/l*sin(theta)))
