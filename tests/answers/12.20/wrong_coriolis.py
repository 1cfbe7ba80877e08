# expect: L=correct, eom=partial, H_conserved=correct, H_is_E=incorrect
# Coriolis term missing from the theta equation; H taken to be the energy.
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
rd, thd = dot(r), dot(theta)
L = m * ((rd * cos(theta) - r * sin(theta) * thd + v) ** 2 + (rd * sin(theta) + r * cos(theta) * thd + 2 * a * t) ** 2) / 2
eom = [Eq(dot(r, 2), r * thd**2 - 2 * a * sin(theta)), Eq(r * dot(theta, 2), -2 * a * cos(theta))]
H_conserved = False
H_is_E = True
