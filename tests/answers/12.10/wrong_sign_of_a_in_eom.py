# expect: eom=incorrect, period=correct
# Sign slip in the equation (the support's acceleration entering as g - a) while the period is quoted correctly.
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [Eq(l * dot(theta, 2), -(g - a) * sin(theta))]
period = 2 * pi * sqrt(l / (g + a))
