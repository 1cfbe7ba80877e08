# expect: H=partial, H_p=incorrect, H_diff=incorrect, Hp_conserved=incorrect
# The momentum in S' taken as m r^2 phip' (relative angular velocity), giving H' = T_rel - m w^2 r^2/2 + V;
# and H' declared not conserved "because the frame rotates".
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r, phip = coordinates("r phip")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
H = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + k * r**2 / 2
H_p = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - m * omega**2 * r**2 / 2 + k * r**2 / 2
H_diff = -m * omega**2 * r**2 / 2
H_conserved = True
H_is_E = True
Hp_conserved = False
Hp_is_E = False
