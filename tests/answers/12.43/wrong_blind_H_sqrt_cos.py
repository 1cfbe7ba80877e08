# expect: H=incorrect, hamilton=correct, eom=correct
from lagrade.answer import *

m, l, g = parameters("m l g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
# cos(theta) replaced by sqrt(1 - sin(theta)**2): the sign is lost once |theta| > pi/2
H = p_theta**2/(2*m*l**2) - m*g*l*sqrt(1 - sin(theta)**2)
hamilton = [Eq(dot(theta), p_theta/(m*l**2)), Eq(p_theta.diff(t), -m*g*l*sin(theta))]
eom = [Eq(dot(theta, 2), -g/l*sin(theta))]
