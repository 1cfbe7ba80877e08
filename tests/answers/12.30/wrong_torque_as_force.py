# expect: eom_xy=correct, eom=correct, N=incorrect
# Gave the multiplier (a torque) as the normal force.
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r = coordinates("x y r")
eom_xy = [Eq(dot(x, 2) * cos(omega * t) + dot(y, 2) * sin(omega * t), 0)]
eom = [Eq(dot(r, 2), omega**2 * r)]
lam = 2 * m * omega * r * dot(r)
N = 2 * m * omega * r * dot(r)
