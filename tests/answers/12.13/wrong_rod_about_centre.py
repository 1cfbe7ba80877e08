# expect: L=incorrect, eom=partial, cyclic=correct, conserved=correct, period=incorrect
# Rod's moment of inertia taken about its centre (M*l**2/12) instead of about the pivot O.
from lagrade.answer import *

M, l, R, g = parameters("M l R g")
theta, psi = coordinates("theta psi")
L = (M * l**2 / 12 + M * l**2) * dot(theta) ** 2 / 2 + M * R**2 * dot(psi) ** 2 / 4 + 3 * M * g * l * cos(theta) / 2
eom = [Eq(13 * l * dot(theta, 2), -18 * g * sin(theta)), Eq(dot(psi, 2), 0)]
cyclic = ["psi"]
conserved = [dot(psi)]
period = 2 * pi * sqrt(13 * l / (18 * g))
