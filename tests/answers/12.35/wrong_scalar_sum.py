# expect: Q=correct, eom=correct, solution=correct, N=correct, reaction=incorrect, reaction_t=incorrect, reaction_angle=incorrect
# Normal force and friction added as numbers, N (1 + mu), and the angle measured from the tangent.
from lagrade.answer import *

m, a, c, mu = parameters("m a c mu")
v0 = symbols("v0")
theta = coordinates("theta")
K = c * a / m + mu
Q = {"theta": -(c * a**3 + mu * m * a**2) * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -K * dot(theta)**2)]
solution = {"theta": log(1 + K * v0 * t / a) / K}
N = m * a * dot(theta)**2
reaction = m * a * dot(theta)**2 * (1 + mu)
reaction_t = m * v0**2 * (1 + mu) / (a * (1 + K * v0 * t / a)**2)
reaction_angle = atan(1 / mu)
