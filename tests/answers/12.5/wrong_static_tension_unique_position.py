# expect: Q_a=correct, Q_b=correct, dW=correct, S_t=incorrect, equilibrium=correct, neutral=incorrect
# Tension taken as m1*g*sin(alpha) during the motion; and the equilibrium believed to fix one position l1.
from sympy import symbols, sin

m1, m2, g, alpha, beta, S = symbols("m1 m2 g alpha beta S")
delta_l1, delta_l = symbols("delta_l1 delta_l")
Qg = g * (m1 * sin(alpha) - m2 * sin(beta))
Q_a = {"l1": Qg, "l": m2 * g * sin(beta) - S}
dW_a = Qg * delta_l1 + (m2 * g * sin(beta) - S) * delta_l
Q_b = {"l1": Qg}
dW_b = Qg * delta_l1
S_t = m1 * g * sin(alpha)
equilibrium = m2 * sin(beta) / sin(alpha)
neutral = False
