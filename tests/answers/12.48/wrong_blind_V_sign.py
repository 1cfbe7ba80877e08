# expect: L=incorrect, H=incorrect, H_conserved=correct, dH_dt=incorrect, H_is_E=correct
from lagrade.answer import *

m, k, a = parameters("m k a")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
L = m*(dot(r)**2 + r**2*dot(theta)**2)/2 - k*exp(-a*t)/r
H = p_r**2/(2*m) + p_theta**2/(2*m*r**2) + k*exp(-a*t)/r
hamilton = [Eq(dot(r), p_r/m), Eq(dot(theta), p_theta/(m*r**2)),
            Eq(p_r.diff(t), p_theta**2/(m*r**3) + k*exp(-a*t)/r**2), Eq(p_theta.diff(t), 0)]
H_conserved = False
dH_dt = -a*k*exp(-a*t)/r
H_is_E = True
