# expect: L=incorrect, eom=incorrect, solution=incorrect, H_conserved=correct
from lagrade.answer import *

m, g, omega = parameters("m g omega")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = m*dot(r)**2/2 - m*g*r*sin(omega*t)
eom = [Eq(dot(r, 2), -g*sin(omega*t))]
solution = {"r": r0 + v0*t + g*sin(omega*t)/omega**2 - g*t/omega}
H_conserved = False
