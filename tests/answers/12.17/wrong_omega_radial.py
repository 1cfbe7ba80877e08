# expect: omega=partial, S_t=incorrect
# Radial frequency taken as that of the bare centrifugal barrier with m1 only (missing factor 3 and m1 + m2),
# and the tension as m2*g (m2 at rest).
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0 = Symbol("r0")
r, phi, theta = coordinates("r phi theta")
S_t = m2 * g
omega = [sqrt(m2 * g / (m1 * r0)), sqrt(g / (l - r0))]
