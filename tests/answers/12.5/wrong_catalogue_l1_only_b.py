# expect: Q_a=missing, Q_b=correct, dW=correct, equilibrium=correct, neutral=correct
# The catalogue's names with l1 as the only coordinate (b) only: Q is graded as Q_b, and (a), which the
# problem asks too, is missing (half of the generalized force's credit). The tension as the catalogue writes it.
from lagrade.answer import *

m1, m2, g, alpha, beta, l = parameters("m1 m2 g alpha beta l")
l1 = coordinates("l1")
delta_l1 = symbols("delta_l1")
V = -m1 * g * l1 * sin(alpha) - m2 * g * (l - l1) * sin(beta)
Q = {"l1": -diff(V, l1)}
dW = Q["l1"] * delta_l1
S_t = m1 * m2 * g * (sin(alpha) + sin(beta)) / (m1 + m2)
equilibrium = Eq(m1 * sin(alpha), m2 * sin(beta))
neutral = True
