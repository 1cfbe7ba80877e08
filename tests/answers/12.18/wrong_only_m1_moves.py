# expect: L=incorrect, eom=incorrect, a=incorrect, S_t=incorrect, solution=incorrect
# m2's kinetic energy forgotten: T = m1*r'**2/2, so r'' = -m2*g/m1.
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = m1 * dot(r) ** 2 / 2 + m2 * g * (l - r)
eom = [Eq(m1 * dot(r, 2), -m2 * g)]
a = -m2 * g / m1
S_t = m2 * g
solution = {"r": r0 + v0 * t - m2 * g * t**2 / (2 * m1)}
