# Solution written with exponentials; eom multiplied by m; L with a total derivative d/dt(r*t).
from lagrade.answer import *

m, g, omega, r0, v0 = parameters("m g omega r0 v0")
r = coordinates("r")
L = m * dot(r) ** 2 / 2 + m * omega**2 * r**2 / 2 - m * g * r * sin(omega * t) + r + t * dot(r)
eom = m * dot(r, 2) - m * omega**2 * r + m * g * sin(omega * t)
A = (r0 + v0 / omega - g / (2 * omega**2)) / 2
B = (r0 - v0 / omega + g / (2 * omega**2)) / 2
solution = {r: A * exp(omega * t) + B * exp(-omega * t) + g * sin(omega * t) / (2 * omega**2)}
H_conserved = False
