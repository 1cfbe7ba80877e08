"""Problem 12.42: simple harmonic motion from Hamilton's equations.

L = m x'^2/2 - k x^2/2, p_x = m x', H = p_x^2/(2m) + k x^2/2.
x' = dH/dp_x = p_x/m, p_x' = -dH/dx = -k x  ->  x'' = -(k/m) x, omega = sqrt(k/m);
x = x0 cos(omega t) + (v0/omega) sin(omega t) (= A cos(omega t + delta)), p_x = m x'.
The phase-space orbit is the ellipse p_x^2/(2m) + k x^2/2 = E.
"""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x0, v0 = symbols("x0 v0")
x = Function("x")(t)
p_x = Function("p_x")(t)

H = p_x**2 / (2 * m) + k * x**2 / 2
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -k * x)]
omega = sqrt(k / m)
solution = {"x": x0 * cos(omega * t) + v0 / omega * sin(omega * t)}
