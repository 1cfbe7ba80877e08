# expect: hamilton=partial, hamilton_fixed=partial
# A special case of the general function where the problem asks the general one (issue 33): hamilton, hamilton_fixed earn partial credit.
# Equivalent forms: rows multiplied out, written as expressions = 0, reordered; phip' + omega grouped.
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r, phi, phip = coordinates("r phi phip")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
hamilton_rot = [
    p_phip.diff(t),
    Eq(m * r**2 * (phip.diff(t) + omega), p_phip),
    Eq(m * r**3 * p_r.diff(t), p_phip**2 - m * k * r**4),
    m * r.diff(t) - p_r,
]
hamilton_fixed = [
    Eq(p_phi.diff(t), 0),
    Eq(m * r**3 * p_r.diff(t) + k * m * r**4, p_phi**2),
    Eq(r.diff(t), p_r / m),
    Eq(phi.diff(t) * m * r**2, p_phi),
]
