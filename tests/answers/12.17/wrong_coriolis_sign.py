# expect: L=correct, eom=partial, a=partial, omega=correct
# The variable-length pendulum term with the wrong sign: (l - r)*theta'' + 2*r'*theta' + g*sin(theta) = 0
# (the hanging length is l - r, so its rate is -r', not +r').
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = Symbol("r0")
r, phi, theta = coordinates("r phi theta")
rd, phid, thd = dot(r), dot(phi), dot(theta)
L = m1 * (rd**2 + r**2 * phid**2) / 2 + m2 * (rd**2 + (l - r) ** 2 * thd**2) / 2 + m2 * g * (l - r) * cos(theta)
eom = [
    Eq((m1 + m2) * dot(r, 2), m1 * r * phid**2 - m2 * (l - r) * thd**2 - m2 * g * cos(theta)),
    Eq(r * dot(phi, 2) + 2 * rd * phid, 0),
    Eq((l - r) * dot(theta, 2) + 2 * rd * thd + g * sin(theta), 0),
]
a = {"r": (m1 * r * phid**2 - m2 * (l - r) * thd**2 - m2 * g * cos(theta)) / (m1 + m2),
     "phi": -2 * rd * phid / r, "theta": -(2 * rd * thd + g * sin(theta)) / (l - r)}
omega = [sqrt(3 * m2 * g / ((m1 + m2) * r0)), sqrt(g / (l - r0))]
