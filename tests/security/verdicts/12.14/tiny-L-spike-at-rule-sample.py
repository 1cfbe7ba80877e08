# target: L
# family: tiny
# expect: no-credit
# why: L plus m1*g*l1*theta1*exp(-10**10*(m1 - 43/71)**2): a force spike at m1 = 43/71, within 6.8e-6 of one of the rule's own 24 fixed (crc32-seeded) states, where it is not negligible, and zero where the comparison samples
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
T = (m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)
L = T - V + m1*g*l1*th1*exp(-10**10*(m1 - Rational(43, 71))**2)
