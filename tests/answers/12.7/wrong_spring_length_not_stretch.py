# expect: L=incorrect, eom=partial, omega=correct
# Spring energy k*r**2/2 instead of k*(r - l0)**2/2; the radial equation inherits it, the theta equation is right.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
L = m / 2 * (dot(r) ** 2 + r**2 * dot(theta) ** 2) + m * g * r * cos(theta) - k / 2 * r**2
eom = [
    Eq(m * dot(r, 2), m * r * dot(theta) ** 2 + m * g * cos(theta) - k * r),
    Eq(m * r**2 * dot(theta, 2) + 2 * m * r * dot(r) * dot(theta), -m * g * r * sin(theta)),
]
omega = sqrt(k / m)
