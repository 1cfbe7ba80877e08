# expect: a=incorrect, S_t=incorrect, lam=incorrect
# The example's massless-pulley results copied: pulley inertia ignored, one tension 2 m1 m2 g/(m1 + m2).
from sympy import symbols

m1, m2, I_p, r, g = symbols("m1 m2 I_p a g")
S = 2 * m1 * m2 * g / (m1 + m2)
a = g * (m1 - m2) / (m1 + m2)
S_t = {"S1": S, "S2": S}
lam = {"lam1": -S, "lam2": -S}
