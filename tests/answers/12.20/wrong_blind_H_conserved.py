# expect: T=correct, T_split=correct, T_homogeneous=correct, L=correct, eom=correct, H_conserved=incorrect, H_is_E=incorrect
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
T = m*((dot(r)*cos(theta) - r*sin(theta)*dot(theta) + v)**2 + (dot(r)*sin(theta) + r*cos(theta)*dot(theta) + 2*a*t)**2)/2
Te = expand(T)
T_split = {"T2": m*(dot(r)**2 + r**2*dot(theta)**2)/2,
           "T1": m*(v*(dot(r)*cos(theta) - r*sin(theta)*dot(theta)) + 2*a*t*(dot(r)*sin(theta) + r*cos(theta)*dot(theta))),
           "T0": m*(v**2 + 4*a**2*t**2)/2}
T_homogeneous = False
L = T
eom = [Eq(dot(r, 2), r*dot(theta)**2 - 2*a*sin(theta)), Eq(dot(theta, 2), -2*(dot(r)*dot(theta) + a*cos(theta))/r)]
H_conserved = True
H_is_E = True
