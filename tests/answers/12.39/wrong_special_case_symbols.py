# expect: H=partial, H_p=partial, H_diff=correct, H_conserved=correct, H_is_E=correct, Hp_conserved=correct, Hp_is_E=correct
# A special case of the general function where the problem asks the general one (issue 33): H, H_p earn partial credit.
# Momenta as plain symbols everywhere (allowed in H and in results), H' - H in the momentum of S'.
from sympy import Rational, symbols

m, k, omega = symbols("m k omega", positive=True)
r, p_r, p_phi, p_phip = symbols("r p_r p_phi p_phip")
H = Rational(1, 2) * (p_r**2 + p_phi**2 / r**2) / m + k * r**2 / 2
H_p = H.subs(p_phi, p_phip) - omega * p_phip
H_diff = H_p - H.subs(p_phi, p_phip)
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = False
