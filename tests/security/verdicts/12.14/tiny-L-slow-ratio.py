# target: L
# family: tiny
# expect: no-credit
# why: L plus m1*g*l1*(theta1 + 10001)/(theta1 + 10000): 1e-4 of L, but its Lagrange equations differ from the true ones by about 1e-8, below the sampled states' tolerance
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
T = (m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)
L = T - V + m1*g*l1*(th1 + 10001)/(th1 + 10000)
