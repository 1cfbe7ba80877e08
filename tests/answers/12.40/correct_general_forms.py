# V'(r) from the chain rule of V(r(t)).diff(t), and as Subs(Derivative(V(u), u), u, r) (sympy's V'(r)),
# in rearranged equations; hamilton in the catalogue's rotating frame, hamilton_fixed in the fixed one.
from sympy import Derivative, Eq, Function, Subs, Symbol, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
phi, p_phi = Function("phi")(t), Function("p_phi")(t)
V = Function("V")
u = Symbol("u")
Vprime = V(r).diff(t) / r.diff(t)  # the chain rule: Derivative(V(r(t)), r(t))
hamilton = [
    Eq(m * r.diff(t), p_r),
    Eq(m * r**2 * (phip.diff(t) + omega), p_phip),
    Eq(p_r.diff(t) + Vprime, p_phip**2 / (m * r**3)),
    Eq(p_phip.diff(t), 0),
]
hamilton_fixed = [
    Eq(r.diff(t), p_r / m),
    Eq(phi.diff(t), p_phi / (m * r**2)),
    Eq(p_r.diff(t), p_phi**2 / (m * r**3) - Subs(Derivative(V(u), u), u, r)),
    Eq(p_phi.diff(t), 0),
]
