from lagrade.answer import *

m1, m2, M, R, g, l = parameters("m1 m2 M R g l")
x = coordinates("x")
I_p = M*R**2/2
L = (m1 + m2)*dot(x)**2/2 + I_p*(dot(x)/R)**2/2 + m2*g*x
eom = [Eq((m1 + m2 + M/2)*dot(x, 2), m2*g)]
a = 2*m2*g/(2*m1 + 2*m2 + M)
