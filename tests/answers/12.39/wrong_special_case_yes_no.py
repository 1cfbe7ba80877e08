# expect: H=partial, H_p=partial, H_diff=correct, H_conserved=correct, H_is_E=correct, Hp_conserved=correct, Hp_is_E=correct
# A special case of the general function where the problem asks the general one (issue 33): H, H_p earn partial credit.
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Function, symbols

t = symbols("t")
m, k, omega = symbols("m k omega", positive=True)
r, phi, phip = symbols("r phi phip")
p_r, p_phi, p_phip = symbols("p_r p_phi p_phip")

V = k * r**2 / 2
H = p_r**2 / (2 * m) + p_phi**2 / (2 * m * r**2) + V
H_p = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - omega * p_phip + V
H_diff = -omega * p_phip
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = False

# ---- the form under test
H_conserved = "yes"
Hp_is_E = "no"
