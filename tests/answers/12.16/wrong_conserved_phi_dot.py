# expect: conserved=partial, L=correct, eom=correct
# Says the azimuthal angular velocity phi' is conserved, instead of the angular momentum m*R**2*sin(theta)**2*phi'.
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
L = m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) + m * g * R * cos(theta)
eom = [Eq(dot(theta, 2), sin(theta) * cos(theta) * dot(phi) ** 2 - g / R * sin(theta)),
       Eq(diff(sin(theta) ** 2 * dot(phi), t), 0)]
conserved = [dot(phi), m * R**2 / 2 * (dot(theta) ** 2 + sin(theta) ** 2 * dot(phi) ** 2) - m * g * R * cos(theta)]
