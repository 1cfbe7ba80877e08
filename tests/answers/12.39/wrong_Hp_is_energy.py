# expect: H=partial, H_p=incorrect, H_diff=incorrect, H_conserved=correct, H_is_E=correct, Hp_conserved=correct, Hp_is_E=incorrect
# H' taken to be the energy again (the same function of the momenta as H): the -omega p_phip term is missing.
from lagrade.answer import *

m, k, omega = parameters("m k omega")
r = coordinates("r")
p_r, p_phi, p_phip = momenta("p_r p_phi p_phip")
H = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + k * r**2 / 2
H_p = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) + k * r**2 / 2
H_diff = 0
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = True
