# expect: eom=incorrect, period=incorrect
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
eom = [Eq(dot(theta, 2), -(g - a)/l*sin(theta))]
period = 2*pi*sqrt(l/(g - a))
