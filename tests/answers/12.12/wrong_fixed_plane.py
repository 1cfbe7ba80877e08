# expect: L=incorrect, eom=incorrect, solution=incorrect, H_conserved=correct
# The rotation of the plane left out of T (no centrifugal term omega**2*r).
from lagrade.answer import *

m, g, omega, r0, v0 = parameters("m g omega r0 v0")
r = coordinates("r")
L = m * dot(r) ** 2 / 2 - m * g * r * sin(omega * t)
eom = [Eq(dot(r, 2), -g * sin(omega * t))]
solution = {"r": r0 + v0 * t - g * t / omega + g * sin(omega * t) / omega**2}
H_conserved = False
