"""Problem 12.40: Hamilton's equations for Problem 12.39 (V = k r^2/2) in both frames.

S':  H' = p_r^2/(2m) + p_phip^2/(2 m r^2) - omega p_phip + k r^2/2
     r' = p_r/m,  phip' = p_phip/(m r^2) - omega,  p_r' = p_phip^2/(m r^3) - k r,  p_phip' = 0.
S:   H = p_r^2/(2m) + p_phi^2/(2 m r^2) + k r^2/2
     r' = p_r/m,  phi' = p_phi/(m r^2),  p_r' = p_phi^2/(m r^3) - k r,  p_phi' = 0.
(Same equations once phi' = phip' + omega and p_phi = p_phip.)
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, k, omega = symbols("m k omega", positive=True)
r, phi, phip = Function("r")(t), Function("phi")(t), Function("phip")(t)
p_r, p_phi, p_phip = Function("p_r")(t), Function("p_phi")(t), Function("p_phip")(t)

hamilton_p = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) - k * r),
    Eq(p_phip.diff(t), 0),
]
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(phi.diff(t), p_phi / (m * r**2)),
    Eq(p_r.diff(t), p_phi**2 / (m * r**3) - k * r),
    Eq(p_phi.diff(t), 0),
]
