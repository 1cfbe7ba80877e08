# T written with r**2 = a**2*exp(2*rho); eom solved for the accelerations; Q expanded; the trajectory written
# with log of the squared radius and theta from atan2.
from lagrade.answer import *

m, a, phi, F_r, F_theta = parameters("m a phi F_r F_theta")
b, w = symbols("b w")
u, v = coordinates("u v")
ud, vd = dot(u), dot(v)
rho = u * sin(phi) ** 2 + v * cos(phi) ** 2
r2 = a**2 * exp(2 * rho)
T = m * r2 * (sin(phi) ** 2 * ud**2 + cos(phi) ** 2 * vd**2) / 2
L = T + diff(m * a * u * t, t)
r = sqrt(r2)
Q = {u: r * (F_r * sin(phi) ** 2 - F_theta * sin(phi) * cos(phi)),
     v: r * (F_r * cos(phi) ** 2 + F_theta * sin(phi) * cos(phi))}
eom = [
    Eq(dot(u, 2), cos(phi) ** 2 * vd**2 - sin(phi) ** 2 * ud**2 - 2 * cos(phi) ** 2 * ud * vd),
    Eq(dot(v, 2), sin(phi) ** 2 * ud**2 - cos(phi) ** 2 * vd**2 - 2 * sin(phi) ** 2 * ud * vd),
]
lnr = log((b**2 + w**2 * t**2) / a**2) / 2
th = atan2(w * t, b)
solution = {"u": lnr - th * cos(phi) / sin(phi), "v": lnr + th * sin(phi) / cos(phi)}
