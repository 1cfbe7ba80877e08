# expect: L=correct, eom=correct, a=correct, S_t=correct, solution=incorrect
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = (m1 + m2)*dot(r)**2/2 + m2*g*(l - r)
eom = [(m1 + m2)*dot(r, 2) + m2*g]
a = -m2*g/(m1 + m2)
S_t = m1*m2*g/(m1 + m2)
solution = {"r": r0 + v0*t + a*t**2}
