# L plus a total derivative d/dt(m2*g*r*t + r*phi), eom multiplied through and rearranged, tension from m2's side,
# conserved quantities as 2*p_phi and E + p_phi, omega in the other order and written with the steady angular speed.
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = Symbol("r0")
r, phi, theta = coordinates("r phi theta")
rd, phid, thd = dot(r), dot(phi), dot(theta)

L = (m1 * (rd**2 + r**2 * phid**2) + m2 * (rd**2 + (l - r) ** 2 * thd**2)) / 2 + m2 * g * (l - r) * cos(theta) \
    + diff(m2 * g * r * t + r * phi, t)
eom = [
    m1 * r * dot(phi, 2) + 2 * m1 * rd * phid,
    Eq(2 * (l - r) * dot(theta, 2), 4 * rd * thd - 2 * g * sin(theta)),
    Eq(m2 * g * cos(theta) + (m1 + m2) * dot(r, 2) + m2 * (l - r) * thd**2, m1 * r * phid**2),
]
rdd = (m1 * r * phid**2 - m2 * (l - r) * thd**2 - m2 * g * cos(theta)) / (m1 + m2)
a = {"theta": -(g * sin(theta) - 2 * rd * thd) / (l - r), "r": rdd, "phi": -2 * rd * phid / r}
# from m2 along the cord: S = m2*(g*cos(theta) + (l - r)*theta'**2 + r'')
S_t = m2 * (g * cos(theta) + (l - r) * thd**2 + rdd)
E = m1 * (rd**2 + r**2 * phid**2) / 2 + m2 * (rd**2 + (l - r) ** 2 * thd**2) / 2 - m2 * g * (l - r) * cos(theta)
conserved = [2 * m1 * r**2 * phid, E + m1 * r**2 * phid]
Om2 = m2 * g / (m1 * r0)                      # steady: m1 r0 Om**2 = m2 g
omega = [sqrt(g) / sqrt(l - r0), sqrt(3 * m1 * Om2 / (m1 + m2))]
