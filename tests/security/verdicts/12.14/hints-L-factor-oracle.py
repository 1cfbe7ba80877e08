# target: L
# family: hints
# expect: no-credit
# why: a probe, not an answer: the theta1'^2 term times 5, so that --hints gives the exact ratio and with it the reference coefficient (m1 + m2) l1^2/2
# leak: \b5 times\b
from sympy import *

t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
L = (5*(m1 + m2)/2*l1**2*w1**2 + m2/2*l2**2*w2**2 + m2*l1*l2*w1*w2*cos(th1 - th2)
     + (m1 + m2)*g*l1*cos(th1) + m2*g*l2*cos(th2))
