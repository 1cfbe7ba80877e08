# Right, in unusual forms: the phi equation as d/dt(p_phi) = 0 expanded, cyclic as the coordinate
# itself, the conserved quantities as H and p_phi in momenta, H in csc.
from lagrade.answer import *

m, l, g = parameters("m l g")
theta, phi = coordinates("theta phi")
p_theta, p_phi = momenta("p_theta p_phi")

L = m*l**2*(dot(theta)**2 + (1 - cos(theta)**2)*dot(phi)**2)/2 + m*g*l*cos(theta)
eom = [
    Eq(l*dot(theta, 2), l*sin(theta)*cos(theta)*dot(phi)**2 - g*sin(theta)),
    diff(sin(theta)**2*dot(phi), t),
]
cyclic = [phi]
conserved = [2*p_phi, dot(theta)**2 + sin(theta)**2*dot(phi)**2 - 2*g/l*cos(theta)]
H = p_theta**2/(2*m*l**2) + p_phi**2*csc(theta)**2/(2*m*l**2) - m*g*l*cos(theta)
