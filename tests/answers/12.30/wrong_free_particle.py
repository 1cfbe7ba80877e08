# expect: eom_xy=incorrect, eom=incorrect, N=incorrect
# Ignored the rotation: the bead taken as free along the wire, no centrifugal term, no constraint force.
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r = coordinates("x y r")
eom_xy = [Eq(dot(x, 2), 0)]
eom = [Eq(dot(r, 2), 0)]
lam = 0
N = 0
