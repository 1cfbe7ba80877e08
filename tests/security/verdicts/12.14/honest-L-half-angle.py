# target: L
# family: honest
# expect: full-marks
# why: nothing: cos written through the half angle, cos(u) = 1 - 2*sin(u/2)**2, and a constant added
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
T = (m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
V = -(m1 + m2)*g*l1*cos(th1) - m2*g*l2*cos(th2)

L = T + (m1 + m2)*g*l1*(1 - 2*sin(th1/2)**2) + m2*g*l2*(1 - 2*sin(th2/2)**2) + 7*g*l1*m1
