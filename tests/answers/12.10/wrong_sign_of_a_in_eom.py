# expect: eom=incorrect, period=correct
# eom: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# Sign slip in the equation (the support's acceleration entering as g - a) while the period is quoted correctly.
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [Eq(l * dot(theta, 2), -(g - a) * sin(theta))]
period = 2 * pi * sqrt(l / (g + a))
