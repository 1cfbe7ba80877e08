# expect: Q=correct, eom=correct, solution=correct, N=incorrect, N_t=incorrect
# Reaction written m a^2 theta'^2 (an extra a) and kept at its initial value m v0^2/a.
from lagrade.answer import *

m, a, c = parameters("m a c")
v0 = symbols("v0")
theta = coordinates("theta")
Q = {"theta": -c * a**3 * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -c * a / m * dot(theta)**2)]
solution = {"theta": m / (c * a) * log(1 + c * v0 * t / m)}
N = m * a**2 * dot(theta)**2
N_t = m * v0**2 / a
