# target: omega
# family: floats
# expect: no-credit
# why: each frequency is multiplied by a 3000-digit float 1 + 1e-2900
from sympy import *

t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
A = m1*l1*l2
B = (m1 + m2)*(l1 + l2)*g
C = (m1 + m2)*g**2
right = [sqrt((B - sqrt(B**2 - 4*A*C))/(2*A)), sqrt((B + sqrt(B**2 - 4*A*C))/(2*A))]

c = Float("1." + "0"*2900 + "1", 3000)
omega = [c*w for w in right]
