# expect: L=incorrect, eom=incorrect, omega=incorrect, solution=incorrect
# Forgot the axial motion z' = k*theta' in the kinetic energy.
from lagrade.answer import *

m, a, k, c, theta0, thetadot0 = parameters("m a k c theta0 thetadot0")
theta = coordinates("theta")
L = m * a**2 * dot(theta) ** 2 / 2 - c * (a**2 + k**2 * theta**2) / 2
eom = [Eq(m * a**2 * dot(theta, 2), -c * k**2 * theta)]
w = k / a * sqrt(c / m)
omega = w
solution = {theta: theta0 * cos(w * t) + thetadot0 / w * sin(w * t)}
