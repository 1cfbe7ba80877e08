"""Problem 12.14: planar double pendulum."""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m1, m2, l1, l2, g = symbols("m1 m2 l1 l2 g", positive=True)
th1, th2 = Function("theta1")(t), Function("theta2")(t)
w1, w2 = th1.diff(t), th2.diff(t)

T = (m1 + m2) / 2 * l1**2 * w1**2 + m2 / 2 * l2**2 * w2**2 + m2 * l1 * l2 * w1 * w2 * cos(th1 - th2)
V = -(m1 + m2) * g * l1 * cos(th1) - m2 * g * l2 * cos(th2)
L = T - V

eom_exact = [
    Eq((m1 + m2) * l1 * th1.diff(t, 2) + m2 * l2 * (th2.diff(t, 2) * cos(th1 - th2) + w2**2 * sin(th1 - th2)),
       -(m1 + m2) * g * sin(th1)),
    Eq(l2 * th2.diff(t, 2) + l1 * (th1.diff(t, 2) * cos(th1 - th2) - w1**2 * sin(th1 - th2)), -g * sin(th2)),
]
# small amplitudes: cos -> 1, sin -> angle, drop products of small quantities
eom = [
    Eq((m1 + m2) * l1 * th1.diff(t, 2) + m2 * l2 * th2.diff(t, 2), -(m1 + m2) * g * th1),
    Eq(l1 * th1.diff(t, 2) + l2 * th2.diff(t, 2), -g * th2),
]
# normal modes: m1 l1 l2 W^2 - (m1 + m2)(l1 + l2) g W + (m1 + m2) g^2 = 0, W = omega^2
A = m1 * l1 * l2
B = (m1 + m2) * (l1 + l2) * g
C = (m1 + m2) * g**2
omega = [sqrt((B - sqrt(B**2 - 4 * A * C)) / (2 * A)), sqrt((B + sqrt(B**2 - 4 * A * C)) / (2 * A))]
