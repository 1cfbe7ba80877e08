# expect: L=incorrect, eom=incorrect, solution=incorrect, H_conserved=correct
from lagrade.answer import *

m, g, omega = parameters("m g omega")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = m*(dot(r)**2 + omega**2*r**2)/2 - m*g*r*cos(omega*t)
eom = [Eq(dot(r, 2), omega**2*r - g*cos(omega*t))]
C = g/(2*omega**2)
solution = {r: (r0 - C)*cosh(omega*t) + v0/omega*sinh(omega*t) + C*cos(omega*t)}
H_conserved = False
