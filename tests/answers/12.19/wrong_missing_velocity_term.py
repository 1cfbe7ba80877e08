# expect: T=correct, L=correct, eom=incorrect, Q=correct
# d/dt of the scale factor forgotten: only h2*u'' - dL/du kept (no (d h2/dt)*u' term).
from lagrade.answer import *

m, A, F_x, F_y = parameters("m A F_x F_y")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
h2 = sinh(u) ** 2 + sin(v) ** 2
T = m * A**2 * h2 * (ud**2 + vd**2) / 2
L = T
eom = [
    Eq(h2 * dot(u, 2) - sinh(u) * cosh(u) * (ud**2 + vd**2), 0),
    Eq(h2 * dot(v, 2) - sin(v) * cos(v) * (ud**2 + vd**2), 0),
]
Q = {"u": A * (F_x * sinh(u) * cos(v) + F_y * cosh(u) * sin(v)),
     "v": A * (-F_x * cosh(u) * sin(v) + F_y * sinh(u) * cos(v))}
