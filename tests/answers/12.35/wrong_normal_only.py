# expect: Q=correct, eom=correct, solution=correct, N=correct, reaction=incorrect, reaction_t=incorrect, reaction_angle=incorrect
# The "resultant" reaction given as the normal force alone (friction left out of the reaction).
from lagrade.answer import *

m, a, c, mu = parameters("m a c mu")
v0 = symbols("v0")
theta = coordinates("theta")
K = c * a / m + mu
Q = {"theta": -(c * a**3 + mu * m * a**2) * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -K * dot(theta)**2)]
solution = {"theta": log(1 + K * v0 * t / a) / K}
N = m * a * dot(theta)**2
reaction = m * a * dot(theta)**2
reaction_t = m * v0**2 / (a * (1 + K * v0 * t / a)**2)
reaction_angle = 0
