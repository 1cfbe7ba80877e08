from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
p_r, p_theta = symbols("p_r p_theta")
Pr, Pth = momenta("p_r p_theta")
H = (p_r**2 + p_theta**2/r**2)/(2*m) + k*r**2/2 - k*l0*r - m*g*r*cos(theta)
hamilton = [m*r**2*dot(theta) - Pth,
            Eq(m*g*r*sin(theta), -Pth.diff(t)),
            Eq(k*(r - l0) - m*g*cos(theta) - Pth**2/(m*r**3), -Pr.diff(t)),
            m*dot(r) - Pr]
