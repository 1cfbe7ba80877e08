# expect: omega=incorrect, omega_a=incorrect, fast_mode_diverges_b=incorrect
# Mode equation with (m1 + m2) and m1 swapped in the W**2 coefficient (W**2 term (m1 + m2) l1 l2); limits taken from it.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
A, B, C = (m1 + m2) * l1 * l2, (m1 + m2) * (l1 + l2) * g, (m1 + m2) * g**2
omega = [sqrt((B - sqrt(B**2 - 4 * A * C)) / (2 * A)), sqrt((B + sqrt(B**2 - 4 * A * C)) / (2 * A))]
omega_a = [sqrt(g * (l1 + l2) / (l1 * l2)), sqrt(g / (l1 + l2))]
beats_a = True
omega_b = sqrt(g / (l1 + l2))
fast_mode_diverges_b = False
