# A student who writes theta and p_theta as plain symbols in H: allowed for the Hamiltonian.
from sympy import Eq, Function, Symbol, cos, sin, symbols

t = Symbol("t")
m, l, g = symbols("m l g")
th, p = symbols("theta p_theta")
H = p**2 / (2 * m * l**2) - m * g * l * cos(th)

theta, p_theta = Function("theta")(t), Function("p_theta")(t)
hamilton = [Eq(p_theta.diff(t), -m * g * l * sin(theta)), Eq(m * l**2 * theta.diff(t), p_theta)]
eom = [m * l**2 * theta.diff(t, 2) + m * g * l * sin(theta)]
