# expect: H=correct, H_p=correct, H_conserved=correct, H_is_E=incorrect
# The catalogue's H (H' of the rotating frame) declared the total energy: H_is_E is asked of this H.
from sympy import Function, symbols

m, omega = symbols("m omega", positive=True)
r, p_r, p_phip = symbols("r p_r p_phip")
V = Function("V")
H = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - omega * p_phip + V(r)
H_p = H
H_diff = -omega * p_phip
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = False
