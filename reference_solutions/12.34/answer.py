"""Problem 12.34: bead on a smooth horizontal circular wire with air drag c v^2, no gravity.

T = m a^2 theta'^2/2. The drag -c v^2 (v = a theta' > 0) along the tangent does virtual work
-c a^2 theta'^2 * a dtheta, so Q_theta = -c a^3 theta'^2 and  m a^2 theta'' = -c a^3 theta'^2.
With w = theta': dw/dt = -(c a/m) w^2  ->  1/w = a/v0 + c a t/m  ->  theta' = (v0/a)/(1 + c v0 t/m),
theta = (m/(c a)) ln(1 + c v0 t/m).
Radial equation (rho = a, multiplier = radial force of the wire): -m a theta'^2 = lam, so the wire pulls
toward the centre with N = m a theta'^2 = m v0^2 / (a (1 + c v0 t/m)^2).
"""
from sympy import Eq, Function, log, symbols

t = symbols("t")
m, a, c, v0 = symbols("m a c v0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

Q = {"theta": -c * a**3 * thd**2}
eom = [Eq(m * a**2 * theta.diff(t, 2), -c * a**3 * thd**2)]
solution = {"theta": m / (c * a) * log(1 + c * v0 * t / m)}
N = m * a * thd**2
N_t = m * v0**2 / (a * (1 + c * v0 * t / m) ** 2)
