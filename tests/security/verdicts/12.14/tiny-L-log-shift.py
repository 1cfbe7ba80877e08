# target: L
# family: tiny
# expect: no-credit
# why: L plus m1*g*l1*log(theta1 + 10**11): large in L's value, but its force m1*g*l1/(theta1 + 10**11) is 1e-11 of gravity's in the equations L gives
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
T = (m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)
N = 10**11
L = T - V + m1*g*l1*log(th1 + N)
