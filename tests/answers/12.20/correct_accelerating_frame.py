# L written in the accelerating frame: T2 - 2*m*a*r*sin(theta) (differs from T by a total time derivative),
# eom solved for the accelerations, T expanded term by term.
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
rd, thd = dot(r), dot(theta)
T = (m / 2 * (rd**2 + r**2 * thd**2) + m * v * cos(theta) * rd + 2 * m * a * t * sin(theta) * rd
     + 2 * m * a * t * r * cos(theta) * thd - m * v * r * sin(theta) * thd + m * v**2 / 2 + 2 * m * a**2 * t**2)
T_split = {"T0": m * v**2 / 2 + 2 * m * a**2 * t**2,
           "T1": m * (rd * (v * cos(theta) + 2 * a * t * sin(theta)) + r * thd * (2 * a * t * cos(theta) - v * sin(theta))),
           "T2": m * rd**2 / 2 + m * r**2 * thd**2 / 2}
homogeneous = False
L = m / 2 * (rd**2 + r**2 * thd**2) - 2 * m * a * r * sin(theta)
eom = [Eq(dot(r, 2), r * thd**2 - 2 * a * sin(theta)), Eq(dot(theta, 2), -(2 * rd * thd + 2 * a * cos(theta)) / r)]
H_conserved = False
H_is_E = False
