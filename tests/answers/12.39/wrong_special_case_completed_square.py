# expect: H=partial, H_p=partial, H_diff=correct, H_conserved=correct, H_is_E=correct, Hp_conserved=correct, Hp_is_E=correct
# A special case of the general function where the problem asks the general one (issue 33): H, H_p earn partial credit.
# Equivalent forms: H' with the square completed (kinetic energy relative to S' plus the centrifugal potential),
# H' - H written in the velocities of S', booleans as sympy true/false, H under its alias H_fixed.
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r, phip = coordinates("r phip")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
H_fixed = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + k * r**2 / 2
H_p = p_r**2 / (2 * m) + (p_phip - m * omega * r**2)**2 / (2 * m * r**2) - m * omega**2 * r**2 / 2 + k * r**2 / 2
H_diff = -omega * m * r**2 * (dot(phip) + omega)
H_conserved = S.true
H_is_E = True
Hp_conserved = S.true
Hp_is_E = S.false
