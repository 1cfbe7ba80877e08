"""Exercise 12.4: Atwood machine with a massive pulley (string does not slip).

Coordinates y1, y2 (depths below the axle) and psi (pulley angle), constraints
f1 = y1 - a psi = 0, f2 = y2 + a psi - l = 0 with multipliers lam1, lam2:
  y1:  m1 y1'' - m1 g = lam1
  y2:  m2 y2'' - m2 g = lam2
  psi: I_p psi''     = -a lam1 + a lam2
With y1'' = a psi'' = A, y2'' = -A:  lam1 = m1 (A - g), lam2 = -m2 (A + g), and
I_p A / a^2 = m1 (g - A) - m2 (g + A)  ->  A = g (m1 - m2) / (m1 + m2 + I_p/a^2).
Tensions S = -lam: S1 = m1 (g - A), S2 = m2 (g + A); S1 - S2 = I_p A / a^2 (they differ).
"""
from sympy import symbols

m1, m2, I_p, a, g = symbols("m1 m2 I_p a g", positive=True)

D = m1 + m2 + I_p / a**2
A = g * (m1 - m2) / D
S1 = m1 * g * (2 * m2 + I_p / a**2) / D
S2 = m2 * g * (2 * m1 + I_p / a**2) / D

S_t = {"S1": S1, "S2": S2}
lam = {"lam1": -S1, "lam2": -S2}
a = A  # the answer name `a` is the acceleration (the radius symbol is already inside the expressions)
