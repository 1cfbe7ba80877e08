# L written in cylindrical coordinates with r = a, z = k*theta substituted; eom divided through and
# bare (= 0); omega and the solution written with omega**2 inside a square root.
from lagrade.answer import *

m, a, k, c, theta0, thetadot0 = parameters("m a k c theta0 thetadot0")
theta = coordinates("theta")
r, z = a, k * theta
L = m / 2 * (diff(r, t) ** 2 + r**2 * dot(theta) ** 2 + diff(z, t) ** 2) - c / 2 * (r**2 + z**2)
eom = dot(theta, 2) + c * k**2 / (m * (a**2 + k**2)) * theta
w2 = c * k**2 / (m * a**2 + m * k**2)
omega = sqrt(w2)
solution = {theta: theta0 * cos(sqrt(w2) * t) + thetadot0 * sin(sqrt(w2) * t) / sqrt(w2)}
