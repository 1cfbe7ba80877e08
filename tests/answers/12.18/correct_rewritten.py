# L with an added constant and dF/dt, eom as an expression = 0, a from Newton on each mass,
# tension from m2's side, trajectory written as a completed square.
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = (m1 + m2) / 2 * dot(r) ** 2 - m2 * g * r + 7 * m2 * g * l + diff(r * t, t)
eom = m2 * g + (m1 + m2) * dot(r, 2)
a = -g / (1 + m1 / m2)
S_t = m2 * (g + a)           # m2's downward acceleration is -r''
k = m2 * g / (m1 + m2)
solution = {r: r0 + v0**2 / (2 * k) - k / 2 * (t - v0 / k) ** 2}
