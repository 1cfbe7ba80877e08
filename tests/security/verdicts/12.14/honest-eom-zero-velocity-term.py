# target: eom
# family: honest
# expect: full-marks
# why: the right linearized equations with a velocity term times an exact zero, w1*w2*(sin(theta1 - theta2) - sin(theta1)*cos(theta2) + cos(theta1)*sin(theta2)), left unsimplified
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
a1, a2 = th1.diff(t, 2), th2.diff(t, 2)
eom = [Eq((m1 + m2)*l1*a1 + m2*l2*a2 + m2*l2*w1*w2*(sin(th1 - th2) - sin(th1)*cos(th2) + cos(th1)*sin(th2)), -(m1 + m2)*g*th1),
       Eq(l1*a1 + l2*a2, -g*th2)]
