# expect: L=incorrect, eom=incorrect, eom_small=incorrect, H_conserved=incorrect, H_is_E=incorrect
# The moving support forgotten: a plain pendulum, unforced small-angle equation, H = E conserved.
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
L = m * l**2 * dot(theta) ** 2 / 2 + m * g * l * cos(theta)
eom = [Eq(dot(theta, 2), -g / l * sin(theta))]
eom_small = [Eq(dot(theta, 2), -g / l * theta)]
omega0 = sqrt(g / l)
H_conserved = True
H_is_E = True
