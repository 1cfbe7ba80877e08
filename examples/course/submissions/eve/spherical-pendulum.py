# A right answer (the reference, handed in as is).

from lagrade.answer import *

m, l, g = parameters("m l g")
theta, phi = coordinates("theta phi")
p_theta, p_phi = momenta("p_theta p_phi")

L = m*l**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2 + m*g*l*cos(theta)
eom = [
    Eq(dot(theta, 2), sin(theta)*cos(theta)*dot(phi)**2 - g/l*sin(theta)),
    Eq(dot(phi, 2), -2*cos(theta)/sin(theta)*dot(theta)*dot(phi)),
]
cyclic = ["phi"]
conserved = [
    m*l**2*sin(theta)**2*dot(phi),                                               # p_phi
    m*l**2*(dot(theta)**2 + sin(theta)**2*dot(phi)**2)/2 - m*g*l*cos(theta),     # the energy
]
H = p_theta**2/(2*m*l**2) + p_phi**2/(2*m*l**2*sin(theta)**2) - m*g*l*cos(theta)
