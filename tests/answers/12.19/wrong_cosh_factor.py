# expect: T=incorrect, L=incorrect, eom=incorrect
# Scale factor slip: cosh(u)**2 + sin(v)**2 instead of sinh(u)**2 + sin(v)**2.
from lagrade.answer import *

m, A, F_x, F_y = parameters("m A F_x F_y")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
h2 = cosh(u) ** 2 + sin(v) ** 2
T = m * A**2 * h2 * (ud**2 + vd**2) / 2
L = T
eom = [diff(diff(L, ud), t) - diff(L, u), diff(diff(L, vd), t) - diff(L, v)]
Q = {"u": A * (F_x * sinh(u) * cos(v) + F_y * cosh(u) * sin(v)),
     "v": A * (-F_x * cosh(u) * sin(v) + F_y * sinh(u) * cos(v))}
