# sin^2 written as (1 - cos(2 theta))/2; phi equation expanded; conserved given as a scaled p_phi and E + p_phi.
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
s2 = (1 - cos(2 * theta)) / 2

L = m * R**2 / 2 * (dot(theta) ** 2 + s2 * dot(phi) ** 2) + m * g * R * cos(theta)
eom = [
    Eq(m * R**2 * dot(theta, 2), m * R**2 * sin(theta) * cos(theta) * dot(phi) ** 2 - m * g * R * sin(theta)),
    sin(theta) ** 2 * dot(phi, 2) + 2 * sin(theta) * cos(theta) * dot(theta) * dot(phi),
]
p_phi = m * R**2 * sin(theta) ** 2 * dot(phi)
E = m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) - m * g * R * cos(theta)
conserved = [sin(theta) ** 2 * dot(phi), E + p_phi]
