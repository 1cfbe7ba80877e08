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

# Solved numerically (no closed form) for m = k = tau = 1, x(0) = 1, x'(0) = 0: fourth-order Runge-Kutta, h = 0.01.
import math


def _rates(t, x, v):
    return v, math.exp(-t) / x**2


def _rk4(x, v, t, h):
    k1 = _rates(t, x, v)
    k2 = _rates(t + h / 2, x + h / 2 * k1[0], v + h / 2 * k1[1])
    k3 = _rates(t + h / 2, x + h / 2 * k2[0], v + h / 2 * k2[1])
    k4 = _rates(t + h, x + h * k3[0], v + h * k3[1])
    return (x + h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]),
            v + h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]))


_x, _v, _times, _xs = 1.0, 0.0, [0.0], [1.0]
for _i in range(1, 501):
    _x, _v = _rk4(_x, _v, (_i - 1) * 0.01, 0.01)
    if _i % 25 == 0:
        _times.append(_i * 0.01)
        _xs.append(_x)
solution = {"t": _times, "x": _xs}
