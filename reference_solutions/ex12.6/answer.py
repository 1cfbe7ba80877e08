"""Exercise 12.6: rolling disk on an incline, one coordinate.

T = M y'^2/2 + I theta'^2/2 with I = M R^2/2 and y = R theta; V = M g (l - y) sin(phi).
(a) L = 3 M R^2 theta'^2/4 - M g (l - R theta) sin(phi)
    3 M R^2 theta''/2 = M g R sin(phi)  ->  theta'' = 2 g sin(phi)/(3 R)
    theta(t) = theta0 + w0 t + g sin(phi) t^2/(3 R)
(b) L = 3 M y'^2/4 - M g (l - y) sin(phi)
    3 M y''/2 = M g sin(phi)  ->  y'' = 2 g sin(phi)/3
    y(t) = y0 + v0 t + g sin(phi) t^2/3
Interpretation: uniform acceleration 2 g sin(phi)/3, two thirds of a frictionless block's; the
static friction force does no work (rolling point at rest) and never enters the Lagrangian.
"""
from sympy import Eq, Function, Rational, sin, symbols

t = symbols("t")
M, R, g, l, phi = symbols("M R g l phi", positive=True)
theta0, w0, y0, v0 = symbols("theta0 w0 y0 v0")
theta, y = Function("theta")(t), Function("y")(t)

I = M * R**2 / 2
# (a), the catalogue's formulation: theta
L_a = M / 2 * (R * theta.diff(t)) ** 2 + I / 2 * theta.diff(t) ** 2 - M * g * (l - R * theta) * sin(phi)
eom_a = [Eq(Rational(3, 2) * M * R**2 * theta.diff(t, 2), M * g * R * sin(phi))]
solution_a = {"theta": theta0 + w0 * t + g * sin(phi) * t**2 / (3 * R)}

# (b), graded as its own parts
L_b = M / 2 * y.diff(t) ** 2 + I / 2 * (y.diff(t) / R) ** 2 - M * g * (l - y) * sin(phi)
eom_b = [Eq(y.diff(t, 2), 2 * g * sin(phi) / 3)]
solution_b = {"y": y0 + v0 * t + g * sin(phi) * t**2 / 3}

a = 2 * g * sin(phi) / 3
