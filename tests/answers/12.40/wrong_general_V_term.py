# expect: hamilton=partial, hamilton_fixed=missing
# hamilton: -V(r) where -V'(r) belongs; hamilton_p: the force term left out (graded for the stated V = k r^2/2).
from sympy import Eq, Function, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
V = Function("V")
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) - V(r)),
    Eq(p_phip.diff(t), 0),
]
hamilton_p = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3)),
    Eq(p_phip.diff(t), 0),
]
