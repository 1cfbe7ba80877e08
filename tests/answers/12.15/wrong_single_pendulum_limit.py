# expect: omega_a=partial, beats_a=incorrect, omega_b=correct
# (a) m1 >> m2 read as "the upper bob is a lone pendulum": only one frequency given, and no beats.
from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
omega_a = [sqrt(g / l1)]
beats_a = False
omega_b = sqrt(g / (l1 + l2))
fast_mode_diverges_b = True
