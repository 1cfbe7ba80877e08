# expect: T=incorrect, T_homogeneous=correct, L=incorrect, eom=incorrect, H_conserved=correct, H_is_E=correct
from lagrade.answer import *

m, v, a = parameters("m v a")
r, theta = coordinates("r theta")
xdot = dot(r)*cos(theta) - r*sin(theta)*dot(theta) + v
ydot = dot(r)*sin(theta) + r*cos(theta)*dot(theta) + a*t          # d(a t^2)/dt taken as a*t
T = expand(m*(xdot**2 + ydot**2)/2)
T_split = {"T2": m*(dot(r)**2 + r**2*dot(theta)**2)/2,
           "T1": m*(v*(dot(r)*cos(theta) - r*sin(theta)*dot(theta)) + a*t*(dot(r)*sin(theta) + r*cos(theta)*dot(theta))),
           "T0": m*(v**2 + a**2*t**2)/2}
T_homogeneous = False
L = T
eom = [Eq(dot(r, 2) - r*dot(theta)**2, -a*sin(theta)), Eq(r*dot(theta, 2) + 2*dot(r)*dot(theta), -a*cos(theta))]
H_conserved = False
H_is_E = False
