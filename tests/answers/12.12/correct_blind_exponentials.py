from lagrade.answer import *

m, g, omega = parameters("m g omega")
r0, v0 = symbols("r0 v0")
r = coordinates("r")
L = m*(dot(r)**2 + omega**2*r**2)/2 - m*g*r*sin(omega*t)
eom = [Eq(dot(r, 2), omega**2*r - g*sin(omega*t))]
A = r0/2 + v0/(2*omega) - g/(4*omega**2)
B = r0/2 - v0/(2*omega) + g/(4*omega**2)
solution = {r: A*exp(omega*t) + B*exp(-omega*t) + g*sin(omega*t)/(2*omega**2)}
H_conserved = False
