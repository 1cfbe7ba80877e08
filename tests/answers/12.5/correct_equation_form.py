# Equilibrium given as the equation it satisfies; Q written with sin(beta) terms regrouped.
from sympy import Eq, symbols, sin

m1, m2, g, alpha, beta, S = symbols("m1 m2 g alpha beta S")
delta_l1, delta_l = symbols("delta_l1 delta_l")
Q_a = {"l1": m1 * g * sin(alpha) - m2 * g * sin(beta), "l": -(S - m2 * g * sin(beta))}
dW_a = m1 * g * sin(alpha) * delta_l1 + m2 * g * sin(beta) * (delta_l - delta_l1) - S * delta_l
Q_b = {"l1": m1 * g * sin(alpha) - m2 * g * sin(beta)}
dW_b = (m1 * g * sin(alpha) - m2 * g * sin(beta)) * delta_l1
S_t = g * (sin(alpha) + sin(beta)) / (1 / m1 + 1 / m2)
equilibrium = Eq(m1 * sin(alpha), m2 * sin(beta))
neutral = True
