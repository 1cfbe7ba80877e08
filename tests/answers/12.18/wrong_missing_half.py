# expect: L=incorrect, solution=incorrect, a=correct
# Missing 1/2 in T (and in the t**2 term of the solution).
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = (m1 + m2) * dot(r) ** 2 + m2 * g * (l - r)
a = -m2 * g / (m1 + m2)
solution = {"r": r0 + v0 * t - m2 * g * t**2 / (m1 + m2)}
