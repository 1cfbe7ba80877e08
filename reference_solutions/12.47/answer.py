"""Problem 12.47: mass on a spring whose upper end accelerates upward (a0).

Support height s = a0 t^2/2; x = extension; the mass is at height y = s - l0 - x, y' = a0 t - x'.
L = m (a0 t - x')^2/2 - k x^2/2 - m g (a0 t^2/2 - l0 - x).
d/dt dL/dx' = m (x'' - a0), dL/dx = -k x + m g  ->  m x'' = m (g + a0) - k x.
p_x = m (x' - a0 t), x' = p_x/m + a0 t, H = p_x x' - L = p_x^2/(2m) + a0 t p_x + k x^2/2 + m g (a0 t^2/2 - l0 - x).
x' = p_x/m + a0 t, p_x' = m g - k x.  Oscillation about x_eq = m (g + a0)/k with period 2 pi sqrt(m/k).
"""
from sympy import Eq, Function, pi, sqrt, symbols

t = symbols("t")
m, k, g, a0, l0 = symbols("m k g a0 l0", positive=True)
x, p_x = Function("x")(t), Function("p_x")(t)
xd = x.diff(t)

height = a0 * t**2 / 2 - l0 - x
L = m * (a0 * t - xd) ** 2 / 2 - k * x**2 / 2 - m * g * height
eom = [Eq(m * x.diff(t, 2), m * (g + a0) - k * x)]
H = p_x**2 / (2 * m) + a0 * t * p_x + k * x**2 / 2 + m * g * height
hamilton = [Eq(x.diff(t), p_x / m + a0 * t), Eq(p_x.diff(t), m * g - k * x)]
period = 2 * pi * sqrt(m / k)
H_conserved = False  # H depends on t explicitly (dH/dt = partial H/partial t = a0*p_x + m*g*a0*t)
H_is_E = False       # H = E + a0*t*p_x, E = T + V of the mass in the ground frame
