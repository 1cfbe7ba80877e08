# target: L
# family: tiny
# expect: no-credit
# why: L times (x + 10**11)/(l3 + 10**11): a coordinate-dependent factor whose force is 1e-11 of gravity's, built of atoms never weighed
from sympy import *
t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3 = symbols("m1 m2 m3 m4 g l1 l2 l3", positive=True)
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
xd, yd, zd = x.diff(t), y.diff(t), z.diff(t)
T = m1/2*(xd + yd)**2 + m2/2*(xd - yd)**2 + m3/2*(zd - xd)**2 + m4/2*(xd + zd)**2
V = -g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z))
N = 10**11
L = (T - V)*(x + N)/(l3 + N)
