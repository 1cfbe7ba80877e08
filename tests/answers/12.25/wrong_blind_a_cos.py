# expect: L=correct, a=incorrect
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = Rational(7, 10)*M*dot(s)**2 + M*g*s*sin(theta)
a = 5*g*cos(theta)/7
