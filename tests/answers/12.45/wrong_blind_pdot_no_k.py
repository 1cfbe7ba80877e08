# expect: H=correct
from lagrade.answer import *

m, a, k, g = parameters("m a k g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
H = p_theta**2/(2*m*(a**2 + k**2)) + m*g*k*theta
hamilton = [Eq(dot(theta), p_theta/(m*(a**2 + k**2))), Eq(p_theta.diff(t), -m*g)]
