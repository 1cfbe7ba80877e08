# target: eom
# family: tiny
# expect: no-credit
# why: the first equation's gravity term times (m1 + 10**11)/(m2 + 10**11), off by 1e-11*(m1 - m2): a factor of atoms, never weighed
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
N = 10**11
eom = [
    Eq((m1 + m2)*l1*th1.diff(t, 2) + m2*l2*th2.diff(t, 2), -(m1 + m2)*g*th1*(m1 + N)/(m2 + N)),
    Eq(l1*th1.diff(t, 2) + l2*th2.diff(t, 2), -g*th2),
]
