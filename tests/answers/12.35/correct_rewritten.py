# Equivalent forms: forces split into drag + friction, eom times m a^2, theta(t) with the log of a quotient,
# the resultant as the vector sum of its components, the angle via asin.
from lagrade.answer import *

m, a, c, mu = parameters("m a c mu")
v0 = symbols("v0", positive=True)
theta = coordinates("theta")
N_ = m * a * dot(theta)**2
drag = c * (a * dot(theta))**2
Q = {"theta": -(drag + mu * N_) * a}
eom = Eq(m * a**2 * theta.diff(t, 2) + c * a**3 * dot(theta)**2 + mu * m * a**2 * dot(theta)**2, 0)
K = (c * a + mu * m) / m
solution = {theta: log((a + K * v0 * t) / a) / K}
N = N_
reaction = sqrt(N_**2 + (mu * N_)**2)
v = v0 / (1 + K * v0 * t / a)
reaction_t = sqrt(1 + mu**2) * m * v**2 / a
reaction_angle = asin(mu / sqrt(1 + mu**2))
