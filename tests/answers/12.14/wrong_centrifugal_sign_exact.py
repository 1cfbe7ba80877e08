# expect: eom_exact=partial, L=correct, eom=correct, omega=correct
# eom_exact: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# In the exact theta2 equation the centrifugal term has the wrong sign (+l1*theta1'**2*sin(theta1 - theta2) on the left).
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
th1, th2 = coordinates("theta1 theta2")
w1, w2 = dot(th1), dot(th2)
L = (m1 + m2) * l1**2 * w1**2 / 2 + m2 * l2**2 * w2**2 / 2 + m2 * l1 * l2 * w1 * w2 * cos(th1 - th2) \
    + (m1 + m2) * g * l1 * cos(th1) + m2 * g * l2 * cos(th2)
eom_exact = [
    Eq((m1 + m2) * l1 * dot(th1, 2) + m2 * l2 * (dot(th2, 2) * cos(th1 - th2) + w2**2 * sin(th1 - th2)), -(m1 + m2) * g * sin(th1)),
    Eq(l2 * dot(th2, 2) + l1 * (dot(th1, 2) * cos(th1 - th2) + w1**2 * sin(th1 - th2)), -g * sin(th2)),
]
eom = [
    Eq((m1 + m2) * l1 * dot(th1, 2) + m2 * l2 * dot(th2, 2), -(m1 + m2) * g * th1),
    Eq(l1 * dot(th1, 2) + l2 * dot(th2, 2), -g * th2),
]
A, B, C = m1 * l1 * l2, (m1 + m2) * (l1 + l2) * g, (m1 + m2) * g**2
omega = [sqrt((B - sqrt(B**2 - 4 * A * C)) / (2 * A)), sqrt((B + sqrt(B**2 - 4 * A * C)) / (2 * A))]
