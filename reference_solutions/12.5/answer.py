"""Problem 12.5: masses on two smooth inclines (angles alpha, beta) joined over an apex pulley.

Heights below the apex: -l1 sin(alpha) for m1 and -l2 sin(beta) for m2. Gravity does
dW = m1 g sin(alpha) dl1 + m2 g sin(beta) dl2, and the tension pulls both masses toward the pulley,
doing -S (dl1 + dl2) = -S dl (zero when the string length is fixed).
(a) l1, l with l2 = l - l1: dW = g (m1 sa - m2 sb) dl1 + (m2 g sb - S) dl.
(b) l1 only: dW = g (m1 sa - m2 sb) dl1.
Equilibrium: Q_l1 = 0 <=> m1 sin(alpha) = m2 sin(beta), independent of l1 (neutral equilibrium).
Motion: (m1 + m2) l1'' = Q_l1; tension from m1: m1 l1'' = m1 g sa - S.
"""
from sympy import symbols, sin

m1, m2, g, alpha, beta, S = symbols("m1 m2 g alpha beta S", positive=True)
delta_l1, delta_l = symbols("delta_l1 delta_l")

Qg = g * (m1 * sin(alpha) - m2 * sin(beta))
Q_a = {"l1": Qg, "l": m2 * g * sin(beta) - S}        # (a): l1 and l (S or S_t for the tension)
dW_l_free = Qg * delta_l1 + (m2 * g * sin(beta) - S) * delta_l
Q_b = {"l1": Qg}                                     # (b), the catalogue's Q: l1 alone
dW = Qg * delta_l1
S_t = m1 * m2 * g * (sin(alpha) + sin(beta)) / (m1 + m2)
equilibrium = m2 * sin(beta) / sin(alpha)   # the m1 that balances: m1 sin(alpha) = m2 sin(beta)
neutral = True
