# Equivalent forms: Q with |theta'|, eom divided through and unsolved, the log split, N as m v^2/a, N_t expanded.
from lagrade.answer import *

m, a, c = parameters("m a c")
v0 = symbols("v0", positive=True)
theta = coordinates("theta")
Q = {theta: -c * a**3 * dot(theta) * Abs(dot(theta))}
eom = [theta.diff(t, 2) + c * a / m * dot(theta)**2]
solution = {"theta": (log(m + c * v0 * t) - log(m)) * m / (c * a)}
v = a * dot(theta)
N = m * v**2 / a
N_t = m**3 * v0**2 / (a * (m + c * v0 * t) ** 2)
