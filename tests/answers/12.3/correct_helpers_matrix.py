# Written with lagrade's helpers and a matrix form M q'' + K q = 0.
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
q = Matrix([x1, x2])
Mm = m * eye(2)
K = k * Matrix([[2, -1], [-1, 1]])

L = (q.diff(t).T * Mm * q.diff(t))[0] / 2 - (q.T * K * q)[0] / 2
eom = list(Mm * q.diff(t, 2) + K * q)
