# L plus the gauge term d/dt(r*theta); theta equation as d/dt(p_theta) = dL/dtheta; omega from the period.
from sympy import Eq, Function, pi, cos, sin, sqrt, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)

L = m / 2 * (r.diff(t) ** 2 + r**2 * theta.diff(t) ** 2) + m * g * r * cos(theta) \
    - k / 2 * (r - l0) ** 2 + (r * theta).diff(t)
eom = [
    Eq((m * r**2 * theta.diff(t)).diff(t), -m * g * r * sin(theta)),
    Eq(r.diff(t, 2), r * theta.diff(t) ** 2 + g * cos(theta) + k / m * (l0 - r)),
]
T_period = 2 * pi * sqrt(m / k)
omega = 2 * pi / T_period

# (a) the ratio of the radial and pendulum frequencies squared, k*l0/(m*g), made large; (b) theta held at 0
from sympy import oo

pendulum = {k * l0 / (m * g): oo}
oscillator = {theta: 0}
