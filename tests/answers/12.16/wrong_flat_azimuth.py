# expect: L=incorrect, eom=incorrect, conserved=correct
# Azimuthal speed taken as R*phi' instead of R*sin(theta)*phi' (L and the eom derived from it); the constants are quoted right.
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m * R**2 / 2 * (dot(theta) ** 2 + dot(phi) ** 2) + m * g * R * cos(theta)
eom = [Eq(dot(theta, 2), -g / R * sin(theta)), Eq(dot(phi, 2), 0)]
conserved = [m * R**2 * sin(theta) ** 2 * dot(phi),
             m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) - m * g * R * cos(theta)]
