# expect: hamilton=partial, hamilton_fixed=missing
# The force term with the wrong sign: p_r' = ... + V'(r).
from sympy import Eq, Function, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
V = Function("V")
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(phip.diff(t), p_phip / (m * r**2) - omega),
    Eq(p_r.diff(t), p_phip**2 / (m * r**3) + V(r).diff(r)),
    Eq(p_phip.diff(t), 0),
]
hamilton_p = hamilton
