# expect: L=correct, eom=correct, omega=correct, solution=incorrect
# Right frequency, but the sine term not divided by omega: theta'(0) is wrong.
from lagrade.answer import *

m, a, k, c, theta0, thetadot0 = parameters("m a k c theta0 thetadot0")
theta = coordinates("theta")
L = m * (a**2 + k**2) * dot(theta) ** 2 / 2 - c * (a**2 + k**2 * theta**2) / 2
eom = [Eq(m * (a**2 + k**2) * dot(theta, 2), -c * k**2 * theta)]
omega = k * sqrt(c / (m * (a**2 + k**2)))
solution = {theta: theta0 * cos(omega * t) + thetadot0 * sin(omega * t)}
