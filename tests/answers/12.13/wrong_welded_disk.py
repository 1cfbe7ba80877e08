# expect: L=incorrect, eom=partial, cyclic=correct, conserved=correct, period=incorrect
# The disk's rotational inertia attached to theta (as if welded to the rod).
from lagrade.answer import *

M, l, R, g = parameters("M l R g")
theta, psi = coordinates("theta psi")
L = (2 * M * l**2 / 3 + M * R**2 / 4) * dot(theta) ** 2 + M * R**2 * dot(psi) ** 2 / 4 + 3 * M * g * l * cos(theta) / 2
eom = [Eq((8 * l**2 + 3 * R**2) * dot(theta, 2), -9 * g * l * sin(theta)), Eq(dot(psi, 2), 0)]
cyclic = ["psi"]
conserved = [dot(psi)]
period = 2 * pi * sqrt((8 * l**2 + 3 * R**2) / (9 * g * l))
