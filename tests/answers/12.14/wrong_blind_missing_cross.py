# expect: L=incorrect, eom=incorrect, eom_exact=incorrect, omega=incorrect
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
theta1, theta2 = coordinates("theta1 theta2")
L = ((m1 + m2)*l1**2*dot(theta1)**2/2 + m2*l2**2*dot(theta2)**2/2
     + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2))
eom = [Eq(dot(theta1, 2), -g/l1*theta1), Eq(dot(theta2, 2), -g/l2*theta2)]
eom_exact = [Eq(dot(theta1, 2), -g/l1*sin(theta1)), Eq(dot(theta2, 2), -g/l2*sin(theta2))]
omega = [sqrt(g/l1), sqrt(g/l2)]
