"""Problem 12.43: the pendulum's Hamiltonian, p_theta = m l^2 theta'."""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)

H = p_theta**2 / (2 * m * l**2) - m * g * l * cos(theta)
hamilton = [
    Eq(theta.diff(t), H.diff(p_theta)),
    Eq(p_theta.diff(t), -H.diff(theta)),
]
# theta'' = p_theta'/(m l^2) = -(g/l) sin(theta)
eom = Eq(theta.diff(t, 2), -g / l * sin(theta))
