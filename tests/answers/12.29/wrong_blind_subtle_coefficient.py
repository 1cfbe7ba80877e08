# expect: L=correct, eom=correct, a=incorrect
from lagrade.answer import *

m1, m2, M, R, g, l = parameters("m1 m2 M R g l")
x = coordinates("x")
L = (m1 + m2 + M/2)*dot(x)**2/2 + m2*g*x
eom = [Eq((2*m1 + 2*m2 + M)*dot(x, 2), 2*m2*g)]
a = 2*m2*g/(2*m1 + 2*m2 + M) * Rational(101, 100)
