# Frequencies written another way: omega_a in the other order, omega_b as 1/sqrt((l1 + l2)/g), exact modes from W.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
A = m1 * l1 * l2
B = (m1 + m2) * (l1 + l2) * g
C = (m1 + m2) * g**2
disc = sqrt(B**2 - 4 * A * C)
omega = [sqrt((B + disc) / (2 * A)), sqrt(2 * C / (B + disc))]   # second root via W1*W2 = C/A
omega_a = [sqrt(g) / sqrt(l2), sqrt(g) / sqrt(l1)]
beats_a = True
omega_b = 1 / sqrt((l1 + l2) / g)
fast_mode_diverges_b = True
