from lagrade.answer import *

m, l, g = parameters("m l g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
H = p_theta**2/(2*m*l**2) - m*g*l*(1 - 2*sin(theta/2)**2)
hamilton = [Eq(dot(theta), p_theta/(m*l**2)), Eq(p_theta.diff(t), -2*m*g*l*sin(theta/2)*cos(theta/2))]
eom = [Eq(m*l**2*dot(theta, 2), -m*g*l*sin(theta))]
