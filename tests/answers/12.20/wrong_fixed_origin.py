# expect: T=incorrect, T_homogeneous=incorrect, L=incorrect, eom=incorrect, H_conserved=incorrect, H_is_E=incorrect
# The moving origin forgotten: T = m(r'**2 + r**2 theta'**2)/2, "homogeneous", H = E conserved.
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
rd, thd = dot(r), dot(theta)
T = m * (rd**2 + r**2 * thd**2) / 2
T_homogeneous = True
L = T
eom = [Eq(dot(r, 2), r * thd**2), Eq(r * dot(theta, 2) + 2 * rd * thd, 0)]
H_conserved = True
H_is_E = True
