# T with the double-angle identity (cosh(2u) - cos(2v))/4, eom solved for the accelerations,
# Q from the scale factors written with products expanded.
from lagrade.answer import *

m, A, F_x, F_y = parameters("m A F_x F_y")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
T = m * A**2 / 4 * (cosh(2 * u) - cos(2 * v)) * (ud**2 + vd**2)
L = T
h2 = (cosh(2 * u) - cos(2 * v)) / 2
eom = [
    Eq(dot(u, 2), (sinh(u) * cosh(u) * (vd**2 - ud**2) - 2 * sin(v) * cos(v) * ud * vd) / h2),
    Eq(dot(v, 2), (sin(v) * cos(v) * (ud**2 - vd**2) - 2 * sinh(u) * cosh(u) * ud * vd) / h2),
]
Q = {u: A * F_x * sinh(u) * cos(v) + A * F_y * cosh(u) * sin(v),
     v: A * F_y * sinh(u) * cos(v) - A * F_x * cosh(u) * sin(v)}
