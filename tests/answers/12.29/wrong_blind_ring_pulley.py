# expect: L=incorrect, eom=incorrect, a=incorrect
from lagrade.answer import *

m1, m2, M, R, g, l = parameters("m1 m2 M R g l")
x = coordinates("x")
L = (m1 + m2)*dot(x)**2/2 + M*R**2*(dot(x)/R)**2/2 + m2*g*x
eom = [Eq((m1 + m2 + M)*dot(x, 2), m2*g)]
a = m2*g/(m1 + m2 + M)
