# target: eom_reduced
# family: switch
# expect: no-credit
# why: the reduced equation is right only while theta < 50 (theta'' = 0 beyond)
from sympy import *

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
thd = theta.diff(t)
lhs = l*(M + m*sin(theta)**2)*theta.diff(t, 2) + m*l*sin(theta)*cos(theta)*thd**2
rhs = -(M + m)*g*sin(theta)

eom_reduced = Eq(theta.diff(t, 2), Piecewise(((rhs - m*l*sin(theta)*cos(theta)*thd**2)/(l*(M + m*sin(theta)**2)),
                                              theta < 50), (0, True)))
