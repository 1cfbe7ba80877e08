# target: omega
# family: complex
# expect: no-credit
# why: the frequency has an imaginary part 1000*I*sqrt(k/m)
from sympy import *

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)

omega = sqrt(k/m) + 1000*I*sqrt(k/m)
