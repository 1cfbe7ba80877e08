# The catalogue's names: H is the rotating frame's H', in phip(t) and p_phip(t), with the general V(r);
# H_p the same with the square completed; H' - H in the velocities of S'; H_conserved, H_is_E asked of this H'.
from sympy import Function, Rational, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
r, phip = Function("r")(t), Function("phip")(t)
p_r, p_phip = Function("p_r")(t), Function("p_phip")(t)
V = Function("V")
H = Rational(1, 2) * p_r**2 / m + p_phip**2 / (2 * m * r**2) - omega * p_phip + V(r)
H_p = p_r**2 / (2 * m) + (p_phip - m * omega * r**2)**2 / (2 * m * r**2) - m * omega**2 * r**2 / 2 + V(r)
H_diff = -omega * m * r**2 * (phip.diff(t) + omega)
H_conserved = True
H_is_E = False  # asked of this H, which is H'
Hp_conserved = True
Hp_is_E = False
