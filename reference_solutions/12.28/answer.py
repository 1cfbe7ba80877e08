"""Problem 12.28: hoop (m, radius r_h) rolling down the face (angle phi) of a wedge M on a smooth floor.

Hoop centre velocity = (X' + s' cos phi, -s' sin phi); spin s'/r_h, I = m r_h^2.
T = (M + m) X'^2/2 + m cos(phi) X' s' + m s'^2,  V = -m g s sin(phi)
X: (M + m) X'' + m cos(phi) s'' = 0
s: 2 m s'' + m cos(phi) X'' = m g sin(phi)
=> s'' = (M + m) g sin(phi)/(2M + m + m sin^2 phi),  X'' = -m g sin(phi) cos(phi)/(2M + m + m sin^2 phi)
Constant accelerations: from rest, X = X'' t^2/2, s = s0 + s'' t^2/2.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, r_h, g, phi, s0 = symbols("m M r_h g phi s0", positive=True)
X, s = Function("X")(t), Function("s")(t)
Xd, sd = X.diff(t), s.diff(t)

L = (M + m) / 2 * Xd**2 + m * cos(phi) * Xd * sd + m * sd**2 + m * g * s * sin(phi)
eom = [
    Eq((M + m) * X.diff(t, 2) + m * cos(phi) * s.diff(t, 2), 0),
    Eq(2 * s.diff(t, 2) + cos(phi) * X.diff(t, 2), g * sin(phi)),
]
D = 2 * M + m + m * sin(phi) ** 2
a_s = (M + m) * g * sin(phi) / D
a_X = -m * g * sin(phi) * cos(phi) / D
solution = {"X": a_X * t**2 / 2, "s": s0 + a_s * t**2 / 2}
