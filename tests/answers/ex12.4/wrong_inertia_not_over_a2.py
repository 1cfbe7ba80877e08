# expect: a=incorrect, S_t=incorrect, lam=incorrect
# Pulley's kinetic energy written I_p*y1'^2/2 (psi' = y1' instead of y1'/a): effective mass I_p instead of I_p/a^2.
from sympy import symbols

m1, m2, I_p, r, g = symbols("m1 m2 I_p a g")
A = g * (m1 - m2) / (m1 + m2 + I_p)
a = A
S_t = {"S1": m1 * (g - A), "S2": m2 * (g + A)}
lam = {"lam1": -m1 * (g - A), "lam2": -m2 * (g + A)}
