# expect: L=correct, eom=correct, solution=incorrect, H_conserved=incorrect
# H taken as conserved; and the initial velocity condition ignored (v0 dropped from the solution).
from lagrade.answer import *

m, g, omega, r0, v0 = parameters("m g omega r0 v0")
r = coordinates("r")
L = m * (dot(r) ** 2 + omega**2 * r**2) / 2 - m * g * r * sin(omega * t)
eom = [Eq(dot(r, 2), omega**2 * r - g * sin(omega * t))]
solution = {"r": r0 * cosh(omega * t) - g / (2 * omega**2) * sinh(omega * t) + g * sin(omega * t) / (2 * omega**2)}
H_conserved = True
