# expect: L=correct, eom=correct, a=correct, S_t=incorrect, solution=correct
from lagrade.answer import *

m1, m2, l, g = parameters("m1 m2 l g")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = (m1 + m2)*dot(r)**2/2 + m2*g*(l - r)
eom = [Eq(dot(r, 2), -m2*g/(m1 + m2))]
a = -m2*g/(m1 + m2)
S_t = 2*m1*m2*g/(m1 + m2)          # the Atwood-machine formula, not this system's
solution = {r: r0 + v0*t + a*t**2/2}
