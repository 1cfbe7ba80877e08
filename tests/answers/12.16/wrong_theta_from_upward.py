# expect: L=incorrect, eom=partial, conserved=partial
# Sign of V as if theta were measured from the upward vertical; the theta equation and the energy carry the wrong sign of g.
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) - m * g * R * cos(theta)
eom = [Eq(dot(theta, 2), sin(theta) * cos(theta) * dot(phi) ** 2 + g / R * sin(theta)),
       Eq(diff(m * R**2 * sin(theta) ** 2 * dot(phi), t), 0)]
conserved = [m * R**2 * sin(theta) ** 2 * dot(phi),
             m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) + m * g * R * cos(theta)]
