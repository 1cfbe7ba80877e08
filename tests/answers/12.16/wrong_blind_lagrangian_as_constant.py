# expect: L=correct, eom=correct
from lagrade.answer import *

m, R, g = parameters("m R g")
theta, phi = coordinates("theta phi")
T = m*R**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2
V = -m*g*R*cos(theta)
L = T - V
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (theta, phi)]
conserved = [m*R**2*sin(theta)**2*dot(phi), T - V]     # T - V is not the energy
