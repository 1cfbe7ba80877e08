# expect: H=incorrect, H_p=incorrect, Hp_is_E=incorrect
# H' taken to be the energy T + V(r) written in the momenta of S' (the catalogue's H): the -omega p_phip term is missing.
from sympy import Function, symbols

m, omega = symbols("m omega", positive=True)
r, p_r, p_phip = symbols("r p_r p_phip")
V = Function("V")
H = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) + V(r)
H_p = H
H_diff = -omega * p_phip
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = True
