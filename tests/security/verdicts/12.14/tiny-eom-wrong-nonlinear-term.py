# target: eom
# family: tiny
# expect: no-credit
# why: the linearized equations plus an invented term 100*(m1 + m2)*g*theta1**2: neither the small-oscillation equations nor the exact ones (eom_exact), yet any nonlinear rows with the right linear part are taken for "the exact equations"
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
a1, a2 = th1.diff(t, 2), th2.diff(t, 2)
eom = [Eq((m1 + m2)*l1*a1 + m2*l2*a2, -(m1 + m2)*g*th1 + 100*(m1 + m2)*g*th1**2),
       Eq(l1*a1 + l2*a2, -g*th2)]
