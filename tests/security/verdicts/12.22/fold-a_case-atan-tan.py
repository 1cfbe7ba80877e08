# target: a_case
# family: fold
# expect: no-credit
# why: g replaced by atan(sin(g)/cos(g)), which is g only for |g| < pi/2
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

G = atan(sin(g)/cos(g))
a_case = {"m1": -Rational(23, 25)*G, "m2": g/25, "m3": Rational(9, 25)*g, "m4": Rational(13, 25)*g}
