# expect: eom=correct, period=incorrect
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [l*dot(theta, 2) + (g + a)*sin(theta)]
period = pi*sqrt(l/(g + a))
