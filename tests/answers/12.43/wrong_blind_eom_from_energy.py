# expect: H=correct, hamilton=correct, eom=incorrect
from lagrade.answer import *

m, l, g = parameters("m l g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
H = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)
hamilton = [Eq(dot(theta), p_theta/(m*l**2)), Eq(p_theta.diff(t), -m*g*l*sin(theta))]
# dE/dt = 0 written as the equation of motion: it also allows the bob to hang at rest at any angle
E = m*l**2*dot(theta)**2/2 - m*g*l*cos(theta)
eom = [Eq(E.diff(t), 0)]
