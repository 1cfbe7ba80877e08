from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
theta1, theta2 = coordinates("theta1 theta2")
L = ((m1 + m2)*l1**2*dot(theta1)**2/2 + m2*l2**2*dot(theta2)**2/2
     + m2*l1*l2*dot(theta1)*dot(theta2)*cos(theta1 - theta2)
     + (m1 + m2)*g*l1*cos(theta1) + m2*g*l2*cos(theta2))
eom = [Eq((m1 + m2)*l1*dot(theta1, 2) + m2*l2*dot(theta2, 2), -(m1 + m2)*g*theta1),
       Eq(l1*dot(theta1, 2) + l2*dot(theta2, 2), -g*theta2)]
eom_exact = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (theta1, theta2)]
# normal modes from det(K - w^2 M) = 0, solved by sympy
w2 = Symbol("w2")
Mm = Matrix([[(m1 + m2)*l1**2, m2*l1*l2], [m2*l1*l2, m2*l2**2]])
K = Matrix([[(m1 + m2)*g*l1, 0], [0, m2*g*l2]])
roots = solve((K - w2*Mm).det(), w2)
omega = tuple(sqrt(r) for r in roots)
