from lagrade.answer import *

m, a, k, g = parameters("m a k g")
theta = coordinates("theta")
p_theta = momenta("p_theta")
I_eff = m*(a**2 + k**2)
H = p_theta**2/(2*I_eff) + m*g*k*theta
hamilton = [Eq(dot(theta), p_theta/I_eff), Eq(p_theta.diff(t), -m*g*k)]
