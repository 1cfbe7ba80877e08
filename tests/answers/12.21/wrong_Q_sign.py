# expect: T=correct, Q=partial, solution=incorrect
# Q_u with +F_theta*cos(phi) (dtheta/du = -sin(phi)*cos(phi) has a minus sign); trajectory with theta(t) = w*t/b
# (uniform rotation instead of the straight line).
from lagrade.answer import *

m, a, phi, F_r, F_theta = parameters("m a phi F_r F_theta")
b, w = symbols("b w")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
r = a * exp(u * sin(phi) ** 2 + v * cos(phi) ** 2)
T = m * r**2 * (sin(phi) ** 2 * ud**2 + cos(phi) ** 2 * vd**2) / 2
Q = {"u": r * sin(phi) * (F_r * sin(phi) + F_theta * cos(phi)), "v": r * cos(phi) * (F_r * cos(phi) + F_theta * sin(phi))}
solution = {"u": log(b / a) - w * t / b * cot(phi), "v": log(b / a) + w * t / b * tan(phi)}
