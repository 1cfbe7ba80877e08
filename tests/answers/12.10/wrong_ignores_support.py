# expect: eom=incorrect, period=incorrect
# Ignores the accelerating support: treats it as an ordinary pendulum with g.
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [Eq(dot(theta, 2), -g / l * sin(theta))]
period = 2 * pi * sqrt(l / g)
