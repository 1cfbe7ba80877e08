# expect: L=correct, eom=partial
# Correct L, but in the x1 equation drops the pull of the second spring on m1 (-2k*x1 + k*x2 written as -k*x1 + k*x2).
from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m * (dot(x1) ** 2 + dot(x2) ** 2) / 2 - k * x1**2 / 2 - k * (x2 - x1) ** 2 / 2
eom = [Eq(m * dot(x1, 2), -k * x1 + k * x2), Eq(m * dot(x2, 2), -k * (x2 - x1))]
