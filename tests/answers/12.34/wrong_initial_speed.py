# expect: solution=incorrect
# theta'(0) taken as v0 instead of v0/a (speed confused with angular speed).
from lagrade.answer import *

m, a, c = parameters("m a c")
v0 = symbols("v0")
theta = coordinates("theta")
Q = {"theta": -c * a**3 * dot(theta)**2}
eom = [Eq(theta.diff(t, 2), -c * a / m * dot(theta)**2)]
solution = {"theta": m / (c * a) * log(1 + c * a * v0 * t / m)}
N = m * a * dot(theta)**2
N_t = m * v0**2 / (a * (1 + c * v0 * t / m) ** 2)
