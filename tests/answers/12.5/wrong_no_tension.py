# expect: Q_a=partial, Q_b=missing, dW=incorrect, S_t=correct, equilibrium=correct, neutral=correct
# (a) The tension's virtual work -S*delta_l forgotten when the string length is a coordinate. Only the (a)
# names are bound: Q_b, which the problem asks too, is missing.
from sympy import symbols, sin

m1, m2, g, alpha, beta = symbols("m1 m2 g alpha beta")
delta_l1, delta_l = symbols("delta_l1 delta_l")
Qg = g * (m1 * sin(alpha) - m2 * sin(beta))
Q_a = {"l1": Qg, "l": m2 * g * sin(beta)}
dW_a = Qg * delta_l1 + m2 * g * sin(beta) * delta_l
S_t = m1 * m2 * g * (sin(alpha) + sin(beta)) / (m1 + m2)
equilibrium = m2 * sin(beta) / sin(alpha)
neutral = True
