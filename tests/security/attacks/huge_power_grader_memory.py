"""effect: exhaust-memory
tries: a short expression whose expansion is huge: (sum of 12 velocity terms)**60 as the Lagrangian, hoping the grader expands or simplifies it.

Memory and time are spent in the grader, which has no rlimit, not in the sandbox.
"""

from lagrade.answer import *

x, y, z = coordinates("x y z")
m1, m2, m3, m4, g, l1, l2, l3 = parameters("m1 m2 m3 m4 g l1 l2 l3")
terms = m1 * dot(x) + m2 * dot(y) + m3 * dot(z) + m4 * x + g * y + l1 * z + l2 * dot(x) * dot(y) + l3 * dot(y) * dot(z) + m1 * x * y + m2 * y * z + m3 * x * z + m4 * g
L = terms ** 60
eom = [Eq(x.diff(t, 2), terms ** 40), Eq(y.diff(t, 2), terms ** 41), Eq(z.diff(t, 2), terms ** 42)]
