# The acceleration bound first under its alias a_m1 (the name a stays the radius), everything multiplied by a**2.
from sympy import symbols

m1, m2, I_p, a, g = symbols("m1 m2 I_p a g")
a_m1 = a**2 * g * (m1 - m2) / (I_p + a**2 * (m1 + m2))
S_t = {"S1": m1 * (g - a_m1), "S2": m2 * (g + a_m1)}
lam = {"lam1": -S_t["S1"], "lam2": -S_t["S2"]}
