# Equivalent forms: L with a total derivative and a constant added, eom multiplied through and unsolved,
# lam from the radial equation written the other way round, N expanded, the angle as an equation.
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
rho = R + r_s
L = m * rho**2 * dot(theta)**2 / 2 - m * g * rho * cos(theta) + 7 + m * g * r_s * sin(theta) * dot(theta)
eom = m * rho**2 * theta.diff(t, 2) - m * g * rho * sin(theta)
lam = -(m * rho * dot(theta)**2 - m * g * cos(theta))
N = 3 * m * g * cos(theta) - 2 * m * g
leave_angle = Eq(3 * cos(theta), 2)
