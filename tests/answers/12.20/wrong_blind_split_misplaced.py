# expect: T=correct, T_homogeneous=correct, L=correct, eom=correct, H_conserved=correct, H_is_E=correct
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
T = m*((dot(r)*cos(theta) - r*sin(theta)*dot(theta) + v)**2 + (dot(r)*sin(theta) + r*cos(theta)*dot(theta) + 2*a*t)**2)/2
# put the cross terms with v into T0 (they are linear in the velocities)
T_split = {"T2": m*(dot(r)**2 + r**2*dot(theta)**2)/2,
           "T1": 2*m*a*t*(dot(r)*sin(theta) + r*cos(theta)*dot(theta)),
           "T0": m*(v**2 + 4*a**2*t**2)/2 + m*v*(dot(r)*cos(theta) - r*sin(theta)*dot(theta))}
T_homogeneous = False
L = T
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (r, theta)]
H_conserved = False
H_is_E = False
