# target: omega
# family: complex
# expect: no-credit
# why: each frequency has an imaginary part 1000*I*sqrt(g/l1)
from sympy import *

t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
A = m1*l1*l2
B = (m1 + m2)*(l1 + l2)*g
C = (m1 + m2)*g**2
right = [sqrt((B - sqrt(B**2 - 4*A*C))/(2*A)), sqrt((B + sqrt(B**2 - 4*A*C))/(2*A))]

omega = [w + 1000*I*sqrt(g/l1) for w in right]
