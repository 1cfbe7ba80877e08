"""Problem 12.24: pendulum whose support moves as X = a cos(omega t).

Bob at (a cos(omega t) + l sin(theta), -l cos(theta)):
T = m (l**2 theta'**2 - 2 a omega l sin(omega t) cos(theta) theta' + a**2 omega**2 sin(omega t)**2)/2, V = -m g l cos(theta).
Lagrange: l theta'' + g sin(theta) = a omega**2 cos(omega t) cos(theta)  (the support's acceleration -a omega**2 cos(omega t)
acts as an inertial force).  Small theta: theta'' + (g/l) theta = (a omega**2/l) cos(omega t): a forced oscillator with
omega0 = sqrt(g/l); steady state theta_p = C cos(omega t), C (g/l - omega**2) = a omega**2/l.
L depends on t explicitly and T is not homogeneous quadratic: H = T2 - T0 + V is neither conserved nor the energy.
"""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, l, g, a, omega = symbols("m l g a omega", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

X = a * cos(omega * t) + l * sin(theta)
Y = -l * cos(theta)
T = m * (X.diff(t) ** 2 + Y.diff(t) ** 2) / 2
V = m * g * Y
L = T - V

eom = [Eq(l * theta.diff(t, 2) + g * sin(theta), a * omega**2 * cos(omega * t) * cos(theta))]
eom_small = [Eq(theta.diff(t, 2) + g / l * theta, a * omega**2 / l * cos(omega * t))]
omega0 = sqrt(g / l)

theta_p = a * omega**2 * cos(omega * t) / (g - l * omega**2)

H_conserved = False
H_is_E = False
