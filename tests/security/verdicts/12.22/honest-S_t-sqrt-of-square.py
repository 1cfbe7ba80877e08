# target: S_t
# family: honest
# expect: full-marks
# why: nothing: the root of a square of positive masses and Abs of a positive sum
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
T = m1/2*(xd + yd)**2 + m2/2*(xd - yd)**2 + m3/2*(zd - xd)**2 + m4/2*(xd + zd)**2
V = -g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z))
D = m1*m2*m3 + m1*m2*m4 + m1*m3*m4 + m2*m3*m4
xdd = g*(m1*m2*m3 + m1*m2*m4 - m1*m3*m4 - m2*m3*m4)/D
ydd = 2*g*m3*m4*(m1 - m2)/D
zdd = 2*g*m1*m2*(m3 - m4)/D
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

S_t = {"S1": 4*g/Abs(1/m1 + 1/m2 + 1/m3 + 1/m4), "S2": 4*g*sqrt(m1**2)/(m1*(1/m1 + 1/m2 + 1/m3 + 1/m4)), "S3": 2*S}
