# expect: L=incorrect, eom_exact=incorrect, eom=correct, omega=correct
# T of the lower bob written as m2*l2**2*theta2'**2/2 without the cross term m2*l1*l2*theta1'*theta2'*cos(theta1 - theta2); exact eom follow from it.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
th1, th2 = coordinates("theta1 theta2")
L = m1 * l1**2 * dot(th1) ** 2 / 2 + m2 * (l1**2 * dot(th1) ** 2 + l2**2 * dot(th2) ** 2) / 2 \
    + (m1 + m2) * g * l1 * cos(th1) + m2 * g * l2 * cos(th2)
eom_exact = [(m1 + m2) * l1 * dot(th1, 2) + (m1 + m2) * g * sin(th1), l2 * dot(th2, 2) + g * sin(th2)]
eom = [
    Eq((m1 + m2) * l1 * dot(th1, 2) + m2 * l2 * dot(th2, 2), -(m1 + m2) * g * th1),
    Eq(l1 * dot(th1, 2) + l2 * dot(th2, 2), -g * th2),
]
A, B, C = m1 * l1 * l2, (m1 + m2) * (l1 + l2) * g, (m1 + m2) * g**2
omega = [sqrt((B - sqrt(B**2 - 4 * A * C)) / (2 * A)), sqrt((B + sqrt(B**2 - 4 * A * C)) / (2 * A))]
