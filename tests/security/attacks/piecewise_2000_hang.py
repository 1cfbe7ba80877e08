"""effect: hang
tries: a Lagrangian that is a Piecewise of 2000 branches: small to send, slow for the grader to sample, compile and compare.

The grader's own comparison, outside the sandbox's limits, on a value built to be expensive.
"""

from lagrade.answer import *

x, y, z = coordinates("x y z")
m1, m2, m3, m4, g = parameters("m1 m2 m3 m4 g")
branches = [(m1 * dot(x) ** 2 / 2 + k * g * x, x < k / 1000) for k in range(2000)]
L = Piecewise(*branches, (0, True))
eom = [Eq(x.diff(t, 2), Piecewise(*[(k * g, y < k / 1000) for k in range(2000)], (0, True)))]
