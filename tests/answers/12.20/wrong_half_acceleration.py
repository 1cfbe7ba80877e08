# expect: T=incorrect, T_split=partial, L=incorrect, eom=incorrect
# d(a t**2)/dt taken as a*t (origin acceleration a instead of 2a).
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
rd, thd = dot(r), dot(theta)
T = m * ((rd * cos(theta) - r * sin(theta) * thd + v) ** 2 + (rd * sin(theta) + r * cos(theta) * thd + a * t) ** 2) / 2
T_split = {"T2": m * (rd**2 + r**2 * thd**2) / 2,
           "T1": m * (v * cos(theta) + a * t * sin(theta)) * rd + m * r * (a * t * cos(theta) - v * sin(theta)) * thd,
           "T0": m * (v**2 + a**2 * t**2) / 2}
T_homogeneous = False
L = T
eom = [Eq(dot(r, 2), r * thd**2 - a * sin(theta)), Eq(r * dot(theta, 2) + 2 * rd * thd, -a * cos(theta))]
