# target: L
# family: near
# expect: no-credit
# why: T times (1000001/1000000)**(1/100), 1 + 1e-8, V not: an algebraic factor off by less than any tolerance (all of L so scaled is a scaled L, tests/test_equivalence_properties.py)
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
T = (m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)

L = T*Rational(1000001, 1000000)**Rational(1, 100) - V
