# expect: L=correct, H=correct, hamilton=correct, H_conserved=incorrect, dH_dt=incorrect, H_is_E=correct
# "H is the energy, so it is conserved": forgets that H depends explicitly on t (dH/dt = partial H/partial t).
from lagrade.answer import *

m, k, a = parameters("m k a")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
L = m * (dot(r) ** 2 + r**2 * dot(theta) ** 2) / 2 + k * exp(-a * t) / r
H = p_r**2 / (2 * m) + p_theta**2 / (2 * m * r**2) - k * exp(-a * t) / r
hamilton = [
    Eq(dot(r), p_r / m),
    Eq(dot(theta), p_theta / (m * r**2)),
    Eq(dot(p_r), p_theta**2 / (m * r**3) - k * exp(-a * t) / r**2),
    Eq(dot(p_theta), 0),
]
H_conserved = True
dH_dt = 0
H_is_E = True
