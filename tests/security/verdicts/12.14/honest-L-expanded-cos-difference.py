# target: L
# family: honest
# expect: full-marks
# why: the right L with cos(theta1 - theta2) expanded and a small-looking but exact 1/2 factor spelled out
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)
c12 = cos(th1)*cos(th2) + sin(th1)*sin(th2)
L = Rational(1, 2)*(m1 + m2)*l1**2*w1**2 + Rational(1, 2)*m2*l2**2*w2**2 + m2*l1*l2*w1*w2*c12 \
    + (m1 + m2)*g*l1*cos(th1) + m2*g*l2*cos(th2)
