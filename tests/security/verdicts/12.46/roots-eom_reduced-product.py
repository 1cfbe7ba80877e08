# target: eom_reduced
# family: roots
# expect: no-credit
# why: the product also allows theta'' = 7 g/l: the reduced equation does not determine the motion
from sympy import *

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
thd = theta.diff(t)
lhs = l*(M + m*sin(theta)**2)*theta.diff(t, 2) + m*l*sin(theta)*cos(theta)*thd**2
rhs = -(M + m)*g*sin(theta)

eom_reduced = Eq((lhs - rhs)*(theta.diff(t, 2) - 7*g/l), 0)
