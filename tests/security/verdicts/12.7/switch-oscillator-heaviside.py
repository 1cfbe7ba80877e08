# target: oscillator
# family: switch
# expect: no-credit
# why: theta is held at Heaviside(m - 50): 0 only for m < 50, theta = 1 (not a motion) beyond
from sympy import *

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)

oscillator = {theta: Heaviside(m - 50)}
