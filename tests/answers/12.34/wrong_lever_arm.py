# expect: Q=incorrect, eom=incorrect, solution=incorrect, N=correct, N_t=incorrect
# Q taken as the force itself (-c a^2 theta'^2), without the lever arm dr/dtheta = a; everything after inherits it.
from lagrade.answer import *

m, a, c = parameters("m a c")
v0 = symbols("v0")
theta = coordinates("theta")
Q = {"theta": -c * a**2 * dot(theta)**2}
eom = [Eq(m * a**2 * theta.diff(t, 2), -c * a**2 * dot(theta)**2)]
solution = {"theta": m / c * log(1 + c * v0 * t / (m * a))}
N = m * a * dot(theta)**2
N_t = m * v0**2 / (a * (1 + c * v0 * t / (m * a)) ** 2)
