# expect: Q=incorrect, eom=incorrect, solution=incorrect, reaction_t=incorrect
# Friction left out of the equation of motion (only drag slows the bead), as in Problem 12.34.
from lagrade.answer import *

m, a, c, mu = parameters("m a c mu")
v0 = symbols("v0")
theta = coordinates("theta")
Q = {"theta": -c * a**3 * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -c * a / m * dot(theta)**2)]
solution = {"theta": m / (c * a) * log(1 + c * v0 * t / m)}
N = m * a * dot(theta)**2
reaction = m * a * dot(theta)**2 * sqrt(1 + mu**2)
reaction_t = m * v0**2 * sqrt(1 + mu**2) / (a * (1 + c * v0 * t / m)**2)
reaction_angle = atan(mu)
