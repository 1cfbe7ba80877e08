# expect: L=correct, eom=correct, omega=incorrect, solution=incorrect
# Took the frequency of the free harmonic attraction, sqrt(c/m), ignoring the wire.
from lagrade.answer import *

m, a, k, c, theta0, thetadot0 = parameters("m a k c theta0 thetadot0")
theta = coordinates("theta")
L = m * (a**2 + k**2) * dot(theta) ** 2 / 2 - c * (a**2 + k**2 * theta**2) / 2
eom = [Eq(m * (a**2 + k**2) * dot(theta, 2), -c * k**2 * theta)]
omega = sqrt(c / m)
solution = {theta: theta0 * cos(omega * t) + thetadot0 / omega * sin(omega * t)}
