"""Problem 12.40: Hamilton's equations for Problem 12.39 (central potential V(r)) in both frames.

S':  H' = p_r^2/(2m) + p_phip^2/(2 m r^2) - omega p_phip + V(r)
     r' = p_r/m,  phip' = p_phip/(m r^2) - omega,  p_r' = p_phip^2/(m r^3) - V'(r),  p_phip' = 0.
S:   H = p_r^2/(2m) + p_phi^2/(2 m r^2) + V(r)
     r' = p_r/m,  phi' = p_phi/(m r^2),  p_r' = p_phi^2/(m r^3) - V'(r),  p_phi' = 0.
(Same equations once phi' = phip' + omega and p_phi = p_phip.)
The catalogue's hamilton is the rotating frame's (hamilton_p the same); the fixed frame's equations are
accepted for hamilton too (tests/answers/12.40/correct_general_text.toml). With the problem's concrete
V = k r^2/2 (V'(r) = k r): tests/answers/12.40/correct_rearranged.py.
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, k, omega = symbols("m k omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
phi, p_phi = Function("phi")(t), Function("p_phi")(t)
V = Function("V")

hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) - V(r).diff(r)),
    Eq(p_phip.diff(t), 0),
]
# also in terms of r and phi (the fixed frame S): H = p_r**2/(2m) + p_phi**2/(2m r**2) + V(r)
hamilton_fixed = [
    Eq(r.diff(t), p_r / m),
    Eq(phi.diff(t), p_phi / (m * r**2)),
    Eq(p_r.diff(t), p_phi**2 / (m * r**3) - V(r).diff(r)),
    Eq(p_phi.diff(t), 0),
]
