# expect: T=incorrect, L=incorrect, eom=incorrect, Q=incorrect, solution=incorrect
# r**2 forgotten (T = m(rho'**2 + theta'**2)/2, as if the metric were flat) -> straight lines in (u, v);
# Q without the factor r.
from lagrade.answer import *

m, a, phi, F_r, F_theta = parameters("m a phi F_r F_theta")
b, w = symbols("b w")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
T = m * (sin(phi) ** 2 * ud**2 + cos(phi) ** 2 * vd**2) / 2
L = T
eom = [Eq(dot(u, 2), 0), Eq(dot(v, 2), 0)]
Q = {"u": sin(phi) * (F_r * sin(phi) - F_theta * cos(phi)), "v": cos(phi) * (F_r * cos(phi) + F_theta * sin(phi))}
solution = {"u": log(b / a) - w * cot(phi) / b * t, "v": log(b / a) + w * tan(phi) / b * t}
