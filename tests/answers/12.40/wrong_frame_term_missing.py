# expect: hamilton=partial, hamilton_fixed=partial
# The fixed-frame equations copied into S': phip' = p_phip/(m r^2), the -omega from the rotation forgotten.
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r, phi, phip = coordinates("r phi phip")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
hamilton_p = [
    Eq(r.diff(t), p_r / m), Eq(phip.diff(t), p_phip / (m * r**2)),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) - k * r), Eq(p_phip.diff(t), 0),
]
hamilton = [
    Eq(r.diff(t), p_r / m), Eq(phi.diff(t), p_phi / (m * r**2)),
    Eq(p_r.diff(t), p_phi**2 / (m * r**3) - k * r), Eq(p_phi.diff(t), 0),
]
