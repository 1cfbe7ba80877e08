# expect: Q_a=incorrect, Q_b=incorrect, dW=incorrect, S_t=incorrect, equilibrium=incorrect, neutral=correct
# Gravity resolved with cos instead of sin along the inclines (angles from the horizontal).
from sympy import symbols, cos

m1, m2, g, alpha, beta, S = symbols("m1 m2 g alpha beta S")
delta_l1, delta_l = symbols("delta_l1 delta_l")
Qg = g * (m1 * cos(alpha) - m2 * cos(beta))
Q_a = {"l1": Qg, "l": m2 * g * cos(beta) - S}
dW_a = Qg * delta_l1 + (m2 * g * cos(beta) - S) * delta_l
Q_b = {"l1": Qg}
dW_b = Qg * delta_l1
S_t = m1 * m2 * g * (cos(alpha) + cos(beta)) / (m1 + m2)
equilibrium = m2 * cos(beta) / cos(alpha)
neutral = True
