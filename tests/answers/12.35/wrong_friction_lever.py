# expect: Q=incorrect, eom=incorrect, solution=incorrect, N=correct, reaction=correct, reaction_t=incorrect, reaction_angle=correct
# Friction's generalized force written mu*N = mu m a theta'^2 without the lever arm a (and carried through).
from lagrade.answer import *

m, a, c, mu = parameters("m a c mu")
v0 = symbols("v0")
theta = coordinates("theta")
K = c * a / m + mu / a
Q = {"theta": -(c * a**3 + mu * m * a) * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -K * dot(theta)**2)]
solution = {"theta": log(1 + K * v0 * t / a) / K}
N = m * a * dot(theta)**2
reaction = m * a * dot(theta)**2 * sqrt(1 + mu**2)
reaction_t = m * v0**2 * sqrt(1 + mu**2) / (a * (1 + K * v0 * t / a)**2)
reaction_angle = atan(mu)
