# target: hamilton
# family: roots
# expect: no-credit
# why: each equation is a product with a second factor: theta' = 7 and p_theta' = 7 m g l are allowed too
from sympy import *

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
H0 = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)

hamilton = [Eq((theta.diff(t) - p_theta/(m*l**2))*(theta.diff(t) - 7), 0),
            Eq((p_theta.diff(t) + m*g*l*sin(theta))*(p_theta.diff(t) - 7*m*g*l), 0)]
