# expect: eom=partial
# The dict form with one acceleration wrong (the hoop's spin forgotten: 1 instead of 2 in front of s'').
from sympy import Eq, Function, cos, sin, solve, symbols

t = symbols("t")
m, M, r_h, g, phi = symbols("m M r_h g phi", positive=True)
X, s = Function("X")(t), Function("s")(t)
eom = {X.diff(t, 2): -m * cos(phi) * s.diff(t, 2) / (M + m), s.diff(t, 2): g * sin(phi) - cos(phi) * X.diff(t, 2)}
