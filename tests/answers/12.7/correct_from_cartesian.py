# T built from Cartesian x = r sin(theta), y = -r cos(theta) (left unsimplified); theta equation divided by m*r.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
x, y = r * sin(theta), -r * cos(theta)

L = m / 2 * (diff(x, t) ** 2 + diff(y, t) ** 2) - m * g * y - k / 2 * (r - l0) ** 2
eom = [
    m * dot(r, 2) - m * r * dot(theta) ** 2 - m * g * cos(theta) + k * (r - l0),
    r * dot(theta, 2) + 2 * dot(r) * dot(theta) + g * sin(theta),
]
omega = sqrt(k) / sqrt(m)

# (a) with the conditions written as equations; (b) keyed by name
pendulum = [Eq(k, oo)]
oscillator = {"theta": 0}
