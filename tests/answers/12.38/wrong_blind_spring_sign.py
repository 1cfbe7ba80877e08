# expect: H=incorrect
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
H = p_r**2/(2*m) + p_theta**2/(2*m*r**2) - m*g*r*cos(theta) - k*(r - l0)**2/2
hamilton = [Eq(dot(r), p_r/m), Eq(dot(theta), p_theta/(m*r**2)),
            Eq(p_r.diff(t), p_theta**2/(m*r**3) + m*g*cos(theta) + k*(r - l0)),
            Eq(p_theta.diff(t), -m*g*r*sin(theta))]
