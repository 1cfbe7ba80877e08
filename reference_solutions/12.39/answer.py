"""Problem 12.39: a central potential V(r) seen from a fixed and from a rotating frame.

S:  L = m (r'^2 + r^2 phi'^2)/2 - V(r);  p_r = m r', p_phi = m r^2 phi';
    H = p_r^2/(2m) + p_phi^2/(2 m r^2) + V(r) = E, conserved (no t).
S': phi = phip + omega t, so L' = m (r'^2 + r^2 (phip' + omega)^2)/2 - V(r);
    p_phip = m r^2 (phip' + omega) = p_phi (same angular momentum);  phip' = p_phip/(m r^2) - omega;
    H' = p_r r' + p_phip phip' - L' = p_r^2/(2m) + p_phip^2/(2 m r^2) - omega p_phip + V(r) = H - omega p_phi.
    No explicit t in L', so H' is conserved, but it is not the energy (it is E - omega * angular momentum).
The catalogue's H is H' (part H; H_p is the same); the fixed frame's H is accepted for part H too
(tests/answers/12.39/correct_symbols.py). H_conserved and H_is_E are asked of the H given for part H. With the problem's concrete V = k r^2/2: correct_completed_square.py.
"""
from sympy import Function, symbols

t = symbols("t")
m, k, omega = symbols("m k omega", positive=True)
r, phi, phip = symbols("r phi phip")
p_r, p_phi, p_phip = symbols("p_r p_phi p_phip")
V = Function("V")

H = p_r**2 / (2 * m) + p_phip**2 / (2 * m * r**2) - omega * p_phip + V(r)
H_p = H
H_diff = -omega * p_phip
H_conserved = True  # asked of the H given (here H'): conserved, L' has no t
H_is_E = False  # H' = E - omega * angular momentum (the fixed frame's H would be E)
Hp_conserved = True
Hp_is_E = False
