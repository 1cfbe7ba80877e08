# target: eom
# family: tiny
# expect: no-credit
# why: theta1's restoring term is (m1 + m2)*g*theta1*(1 + (theta1 + 1/10000)**2): linearized about 0 its coefficient is (m1 + m2)*g*(1 + 10**-8), not (m1 + m2)*g (the linearized check compares Jacobians within 1e-7 and has no exact re-check; the negligible-part rule weighs 1/10000 at random states, where theta1 is not small)
from sympy import *
t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
a1, a2 = th1.diff(t, 2), th2.diff(t, 2)
eom = [Eq((m1 + m2)*l1*a1 + m2*l2*a2, -(m1 + m2)*g*th1*(1 + (th1 + Rational(1, 10000))**2)),
       Eq(l1*a1 + l2*a2, -g*th2)]
