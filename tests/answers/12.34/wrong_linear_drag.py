# expect: Q=incorrect, eom=incorrect, solution=incorrect, N=correct, N_t=incorrect
# Drag taken proportional to v (not v^2): exponential decay instead of 1/(1 + c v0 t/m).
from lagrade.answer import *

m, a, c = parameters("m a c")
v0 = symbols("v0")
theta = coordinates("theta")
Q = {"theta": -c * a**2 * dot(theta)}
eom = [Eq(m * theta.diff(t, 2), -c * dot(theta))]
solution = {"theta": m * v0 / (c * a) * (1 - exp(-c * t / m))}
N = m * a * dot(theta)**2
N_t = m * v0**2 * exp(-2 * c * t / m) / a
