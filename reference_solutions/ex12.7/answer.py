"""Exercise 12.7: Kepler problem in rectangular coordinates.

L = m/2 (x'^2 + y'^2) + k/r, r = sqrt(x^2 + y^2); p_x = m x', p_y = m y'.
H = (p_x^2 + p_y^2)/(2m) - k/r  (= E: L has no explicit t and T is quadratic in the velocities).
x' = p_x/m, y' = p_y/m, p_x' = -dH/dx = -k x/r^3, p_y' = -k y/r^3.
Both x and y appear in H, so neither is cyclic: the conservation of angular momentum, obvious in polar
coordinates (theta cyclic), is hidden here but still holds: d/dt(x p_y - y p_x) = x p_y' - y p_x' = 0.
Constants: L_z = x p_y - y p_x = m (x y' - y x') and E = H.
"""
from sympy import Eq, Function, sqrt, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
r = sqrt(x**2 + y**2)

H = (p_x**2 + p_y**2) / (2 * m) - k / r
hamilton = [
    Eq(x.diff(t), p_x / m),
    Eq(y.diff(t), p_y / m),
    Eq(p_x.diff(t), -k * x / r**3),
    Eq(p_y.diff(t), -k * y / r**3),
]
cyclic = []
conserved = [m * (x * y.diff(t) - y * x.diff(t)), m / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2) - k / r]
