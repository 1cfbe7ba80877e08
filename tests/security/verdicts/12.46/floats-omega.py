# target: omega
# family: floats
# expect: no-credit
# why: the frequency is 1.000000001 times the right one
from sympy import *

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
thd = theta.diff(t)
lhs = l*(M + m*sin(theta)**2)*theta.diff(t, 2) + m*l*sin(theta)*cos(theta)*thd**2
rhs = -(M + m)*g*sin(theta)

omega = Float("1.000000001")*sqrt((M + m)*g/(M*l))
