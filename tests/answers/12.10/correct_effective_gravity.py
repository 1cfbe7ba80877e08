# Effective gravity g + a: eom as an expression = 0, period as 2*pi/omega.
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [dot(theta, 2) + (g + a) / l * sin(theta)]
period = 2 * pi / sqrt((g + a) / l)
