# expect: L_a=correct, L_b=correct, eom_a=correct, eom_b=correct, solution_a=incorrect, solution_b=incorrect, a=correct
# Integrating twice, the factor 1/2 of a*t^2/2 is lost: y = y0 + v0 t + (2 g sin(phi)/3) t^2.
from sympy import Eq, Function, sin, symbols

t = symbols("t")
M, R, g, l, phi = symbols("M R g l phi")
theta0, w0, y0, v0 = symbols("theta0 w0 y0 v0")
theta, y = Function("theta")(t), Function("y")(t)

L_a = 3 * M * R**2 * theta.diff(t) ** 2 / 4 - M * g * (l - R * theta) * sin(phi)
eom_a = [Eq(theta.diff(t, 2), 2 * g * sin(phi) / (3 * R))]
solution_a = {"theta": theta0 + w0 * t + 2 * g * sin(phi) * t**2 / (3 * R)}
L_b = 3 * M * y.diff(t) ** 2 / 4 - M * g * (l - y) * sin(phi)
eom_b = [Eq(y.diff(t, 2), 2 * g * sin(phi) / 3)]
solution_b = {"y": y0 + v0 * t + 2 * g * sin(phi) * t**2 / 3}
a = 2 * g * sin(phi) / 3
