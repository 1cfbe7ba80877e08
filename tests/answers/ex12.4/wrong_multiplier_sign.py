# expect: a=correct, S_t=correct, lam=incorrect
# lam: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# Multipliers given as the tensions themselves (positive): wrong sign for the published convention lam = m y'' - m g.
from sympy import symbols

m1, m2, I_p, r, g = symbols("m1 m2 I_p a g")
D = m1 + m2 + I_p / r**2
a = g * (m1 - m2) / D
S_t = {"S1": m1 * g * (2 * m2 + I_p / r**2) / D, "S2": m2 * g * (2 * m1 + I_p / r**2) / D}
lam = {"lam1": S_t["S1"], "lam2": S_t["S2"]}
