# expect: T=incorrect, Q=partial
# Missing 1/2 in T; Q_v with the sign of the F_x term flipped (dx/dv = -A cosh(u) sin(v)).
from lagrade.answer import *

m, A, F_x, F_y = parameters("m A F_x F_y")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
T = m * A**2 * (sinh(u) ** 2 + sin(v) ** 2) * (ud**2 + vd**2)
Q = {"u": A * (F_x * sinh(u) * cos(v) + F_y * cosh(u) * sin(v)),
     "v": A * (F_x * cosh(u) * sin(v) + F_y * sinh(u) * cos(v))}
