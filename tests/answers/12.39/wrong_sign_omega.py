# expect: H=partial, H_p=incorrect, H_diff=incorrect
# Sign of the rotation term flipped: H' = H + omega p_phi.
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r = coordinates("r")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
H = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + k * r**2 / 2
H_p = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) + omega * p_phip + k * r**2 / 2
H_diff = omega * symbols("p_phip")
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = False
