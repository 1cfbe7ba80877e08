# expect: Q_a=partial, Q_b=missing, dW=incorrect, S_t=correct, equilibrium=correct, neutral=correct
# Formulation (a) in the catalogue's names with S_t: l2 = l - l1 overlooked in delta_l1, so gravity on m2
# is counted with the wrong sign there.
from lagrade.answer import *

m1, m2, g, alpha, beta = parameters("m1 m2 g alpha beta")
l1, l = coordinates("l1 l")
S_t, delta_l1, delta_l = symbols("S_t delta_l1 delta_l")
Q = {"l1": g * (m1 * sin(alpha) + m2 * sin(beta)), "l": m2 * g * sin(beta) - S_t}
dW = Q["l1"] * delta_l1 + Q["l"] * delta_l
S_t = m1 * m2 * g * (sin(alpha) + sin(beta)) / (m1 + m2)
equilibrium = m2 * sin(beta) / sin(alpha)
neutral = True
