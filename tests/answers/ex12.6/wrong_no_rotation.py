# expect: L_a=incorrect, L_b=incorrect, eom_a=incorrect, eom_b=incorrect, solution_a=incorrect, solution_b=incorrect, a=incorrect
# The disk treated as a sliding block: rotational kinetic energy M R^2 theta'^2/4 forgotten, acceleration g sin(phi).
from sympy import Eq, Function, sin, symbols

t = symbols("t")
M, R, g, l, phi = symbols("M R g l phi")
theta0, w0, y0, v0 = symbols("theta0 w0 y0 v0")
theta, y = Function("theta")(t), Function("y")(t)

L_a = M * R**2 * theta.diff(t) ** 2 / 2 - M * g * (l - R * theta) * sin(phi)
eom_a = [Eq(theta.diff(t, 2), g * sin(phi) / R)]
solution_a = {"theta": theta0 + w0 * t + g * sin(phi) * t**2 / (2 * R)}
L_b = M * y.diff(t) ** 2 / 2 - M * g * (l - y) * sin(phi)
eom_b = [Eq(y.diff(t, 2), g * sin(phi))]
solution_b = {"y": y0 + v0 * t + g * sin(phi) * t**2 / 2}
a = g * sin(phi)
