"""Problem 12.39: central force F = -k r (V = k r^2/2) seen from a fixed and from a rotating frame.

S:  L = m (r'^2 + r^2 phi'^2)/2 - V;  p_r = m r', p_phi = m r^2 phi';
    H = p_r^2/(2m) + p_phi^2/(2 m r^2) + V = E, conserved (no t).
S': phi = phip + omega t, so L' = m (r'^2 + r^2 (phip' + omega)^2)/2 - V;
    p_phip = m r^2 (phip' + omega) = p_phi (same angular momentum);  phip' = p_phip/(m r^2) - omega;
    H' = p_r r' + p_phip phip' - L' = p_r^2/(2m) + p_phip^2/(2 m r^2) - omega p_phip + V = H - omega p_phi.
    No explicit t in L', so H' is conserved, but it is not the energy (it is E - omega * angular momentum).
"""
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
