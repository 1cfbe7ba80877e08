# expect: T=incorrect, L=incorrect, eom=incorrect
# sin and cos swapped in the metric (mixing up u and v in the inverse map).
from lagrade.answer import *

m, a, phi, F_r, F_theta = parameters("m a phi F_r F_theta")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
T = m * a**2 * exp(2 * (u * sin(phi) ** 2 + v * cos(phi) ** 2)) * (cos(phi) ** 2 * ud**2 + sin(phi) ** 2 * vd**2) / 2
L = T
eom = [diff(diff(L, ud), t) - diff(L, u), diff(diff(L, vd), t) - diff(L, v)]
