# expect: H=incorrect, H_p=partial, H_diff=correct
# -V(r) where +V(r) belongs (H = T - V) in H, and the V term left out of H_p (graded for the stated V = k r^2/2).
from sympy import Function, symbols

m, omega = symbols("m omega", positive=True)
r, p_r, p_phip = symbols("r p_r p_phip")
V = Function("V")
H = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - omega * p_phip - V(r)
H_p = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - omega * p_phip
H_diff = -omega * p_phip
H_conserved = True
H_is_E = True
Hp_conserved = True
Hp_is_E = False
