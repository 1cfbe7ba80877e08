"""Problem 12.35: the bead of Problem 12.34 on a rough wire (friction coefficient mu), gravity ignored.

Radial equation (rho = a): the wire pushes inward with N = m a theta'^2 (lam = -N, lam positive outward).
Friction mu N = mu m a theta'^2 and drag c a^2 theta'^2 both oppose the motion along the tangent, so
Q_theta = -(c a^3 + mu m a^2) theta'^2 and  theta'' = -K theta'^2  with  K = c a/m + mu.
Then theta' = (v0/a)/(1 + K v0 t/a) and theta = (1/K) ln(1 + K v0 t/a).
Resultant reaction: normal N and friction mu N at right angles: |R| = N sqrt(1 + mu^2), at atan(mu)
from the inward normal, tilted against the motion.
"""
from sympy import Eq, Function, atan, log, sqrt, symbols

t = symbols("t")
m, a, c, mu, v0 = symbols("m a c mu v0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

K = c * a / m + mu
Q = {"theta": -(c * a**3 + mu * m * a**2) * thd**2}
eom = [Eq(theta.diff(t, 2), -K * thd**2)]
solution = {"theta": log(1 + K * v0 * t / a) / K}
N = m * a * thd**2
reaction = N * sqrt(1 + mu**2)
w = (v0 / a) / (1 + K * v0 * t / a)  # theta'(t)
reaction_t = m * a * w**2 * sqrt(1 + mu**2)
reaction_angle = atan(mu)
