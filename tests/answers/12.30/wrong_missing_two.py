# expect: eom_xy=incorrect, eom=correct, N=incorrect
# d/dt(r**2) taken as r*r' (factor 2 lost); Cartesian: component taken perpendicular to the wire instead of along it.
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r = coordinates("x y r")
eom_xy = [Eq(-dot(x, 2) * sin(omega * t) + dot(y, 2) * cos(omega * t), 0)]
eom = [Eq(dot(r, 2), omega**2 * r)]
lam = m * omega * r * dot(r)
N = m * omega * dot(r)
