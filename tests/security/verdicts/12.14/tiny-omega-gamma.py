# target: omega
# family: tiny
# expect: no-credit
# why: the first frequency times gamma(1 + (m1*m2/(m1 + m2)**2)**200): the rule evaluates gamma whole and never weighs its argument
from sympy import *
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
A = m1*l1*l2
B = (m1 + m2)*(l1 + l2)*g
C = (m1 + m2)*g**2
omega = [sqrt((B - sqrt(B**2 - 4*A*C))/(2*A))*gamma(1 + (m1*m2/(m1 + m2)**2)**200),
         sqrt((B + sqrt(B**2 - 4*A*C))/(2*A))]
