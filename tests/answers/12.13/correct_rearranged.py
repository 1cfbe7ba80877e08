# eom unsolved and scaled; conserved given as p_psi; cyclic given as the coordinate itself; period via omega.
from lagrade.answer import *

M, l, R, g = parameters("M l R g")
theta, psi = coordinates("theta psi")
L = (M * l**2 / 3 + M * l**2) * dot(theta) ** 2 / 2 + (M * R**2 / 2) * dot(psi) ** 2 / 2 + M * g * l * cos(theta) * 3 / 2 - 5 * M * g * l
eom = [6 * (4 * M * l**2 * dot(theta, 2) / 3 + 3 * M * g * l * sin(theta) / 2), M * R**2 * dot(psi, 2) / 2]
cyclic = [psi]
conserved = [symbols("p_psi")]
w = sqrt(9 * g / (8 * l))
period = 2 * pi / w
