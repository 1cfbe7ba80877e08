# target: hamilton
# family: switch
# expect: no-credit
# why: the equations are right only while theta < 50 (frozen beyond)
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

hamilton = [Eq(theta.diff(t), Piecewise((p_theta/(m*l**2), theta < 50), (0, True))),
            Eq(p_theta.diff(t), Piecewise((-m*g*l*sin(theta), theta < 50), (0, True)))]
