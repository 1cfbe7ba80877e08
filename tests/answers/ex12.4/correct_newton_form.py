# Tensions written as Newton's second law for each mass, m1 (g - A) and m2 (g + A), with A unsimplified.
from sympy import symbols

m1, m2, I_p, r, g = symbols("m1 m2 I_p a g")   # the radius bound to another Python name
A = (m1 * g - m2 * g) / (m1 + m2 + I_p / r**2)
S_t = {"S2": m2 * (g + A), "S1": m1 * (g - A)}
lam = {"lam1": m1 * A - m1 * g, "lam2": -m2 * A - m2 * g}
a = A
