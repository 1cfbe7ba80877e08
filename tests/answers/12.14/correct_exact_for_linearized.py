# Gives the exact equations where the linearized ones are asked (accepted with a note); cos(theta1 - theta2) expanded; omegas in the other order.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
th1, th2 = coordinates("theta1 theta2")
w1, w2 = dot(th1), dot(th2)
c12 = cos(th1) * cos(th2) + sin(th1) * sin(th2)

L = (m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * c12 \
    + (m1 + m2) * g * l1 * cos(th1) + m2 * g * l2 * cos(th2)
exact = [
    (m1 + m2) * l1 * dot(th1, 2) + m2 * l2 * (dot(th2, 2) * cos(th1 - th2) + w2**2 * sin(th1 - th2)) + (m1 + m2) * g * sin(th1),
    l2 * dot(th2, 2) + l1 * (dot(th1, 2) * cos(th1 - th2) - w1**2 * sin(th1 - th2)) + g * sin(th2),
]
eom = exact
eom_exact = [exact[0] + m2 * exact[1], exact[1]]   # a linear combination: first + m2*second, and second
D = sqrt((m1 + m2) * ((m1 + m2) * (l1 - l2) ** 2 + 4 * m2 * l1 * l2))
omega = [sqrt(g * ((m1 + m2) * (l1 + l2) + D) / (2 * m1 * l1 * l2)),
         sqrt(g * ((m1 + m2) * (l1 + l2) - D) / (2 * m1 * l1 * l2))]
