"""Problem 12.49: pendulum whose string is pulled in at the constant rate k; ell = l0 - k t.

Bob at (ell sin(theta), -ell cos(theta)); v^2 = ell'^2 + ell^2 theta'^2 = k^2 + ell^2 theta'^2.
L = m (k^2 + ell^2 theta'^2)/2 + m g ell cos(theta).
p_theta = m ell^2 theta', H = p_theta theta' - L = p_theta^2/(2 m ell^2) - m k^2/2 - m g ell cos(theta).
E = T + V = m (k^2 + ell^2 theta'^2)/2 - m g ell cos(theta) = H + m k^2: H is not the energy, and neither is
conserved (H depends on t explicitly; the pulling force does work).
Tension (radial equation with ell'' = 0): S = m (ell theta'^2 + g cos(theta)); the bob moves toward the hole at
speed k, so dE/dt = S k = m k (ell theta'^2 + g cos(theta)) (check: dE/dt = dH/dt = partial H/partial t).
theta' = p_theta/(m ell^2), p_theta' = -m g ell sin(theta).
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, l0, k, g = symbols("m l0 k g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
thd = theta.diff(t)
ell = l0 - k * t

L = m * (k**2 + ell**2 * thd**2) / 2 + m * g * ell * cos(theta)
H = p_theta**2 / (2 * m * ell**2) - m * k**2 / 2 - m * g * ell * cos(theta)
hamilton = [Eq(theta.diff(t), p_theta / (m * ell**2)), Eq(p_theta.diff(t), -m * g * ell * sin(theta))]
H_minus_E = -m * k**2
H_conserved = False
H_is_E = False
E_conserved = False
dE_dt = m * k * (ell * thd**2 + g * cos(theta))
