# expect: L=correct, eom=correct, cyclic=incorrect, conserved=incorrect
# theta named cyclic and the rod's angular momentum taken as conserved (gravity exerts a torque).
from lagrade.answer import *

M, l, R, g = parameters("M l R g")
theta, psi = coordinates("theta psi")
L = 2 * M * l**2 * dot(theta) ** 2 / 3 + M * R**2 * dot(psi) ** 2 / 4 + 3 * M * g * l * cos(theta) / 2
eom = [Eq(dot(theta, 2), -9 * g * sin(theta) / (8 * l)), Eq(dot(psi, 2), 0)]
cyclic = ["theta"]
conserved = [4 * M * l**2 * dot(theta) / 3]
period = 2 * pi * sqrt(8 * l / (9 * g))
