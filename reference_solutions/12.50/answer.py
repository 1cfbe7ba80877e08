"""Problem 12.50: F = (k/x^2) exp(-t/tau) on a line (x > 0), k, tau > 0.

V = (k/x) exp(-t/tau) (F = -dV/dx), L = m x'^2/2 - k exp(-t/tau)/x, p_x = m x'.
H = p_x^2/(2m) + k exp(-t/tau)/x = T + V = E: H is the total energy (fixed coordinates, T quadratic in x',
V independent of x'), but dH/dt = partial H/partial t = -(k/(tau x)) exp(-t/tau) != 0: not conserved.
Equation of motion: m x'' = (k/x^2) exp(-t/tau) (no elementary closed-form solution).
"""
from sympy import Eq, Function, exp, symbols

t = symbols("t")
m, k, tau = symbols("m k tau", positive=True)
x, p_x = Function("x")(t), Function("p_x")(t)

L = m * x.diff(t) ** 2 / 2 - k * exp(-t / tau) / x
H = p_x**2 / (2 * m) + k * exp(-t / tau) / x
H_conserved = False
dH_dt = -k * exp(-t / tau) / (tau * x)
H_is_E = True
eom = [Eq(m * x.diff(t, 2), k * exp(-t / tau) / x**2)]
