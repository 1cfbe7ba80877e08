# expect: omega=correct, omega_a=correct, beats_a=correct, omega_b=incorrect, fast_mode_diverges_b=correct
# (b) the heavy lower bob taken to swing on its own rod l2, forgetting that the light upper bob does not hold the string.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
A, B, C = m1 * l1 * l2, (m1 + m2) * (l1 + l2) * g, (m1 + m2) * g**2
omega = [sqrt((B - sqrt(B**2 - 4 * A * C)) / (2 * A)), sqrt((B + sqrt(B**2 - 4 * A * C)) / (2 * A))]
omega_a = [sqrt(g / l1), sqrt(g / l2)]
beats_a = True
omega_b = sqrt(g / l2)
fast_mode_diverges_b = True
