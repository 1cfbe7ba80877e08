# expect: L_a=correct, eom_a=correct, solution_a=correct, L_b=missing, eom_b=missing, solution_b=missing, a=correct
# The catalogue's names and coordinate: theta only (formulation a).
from lagrade.answer import *

M, R, g, l, phi = parameters("M R g l phi")
theta0, w0 = symbols("theta0 w0")
theta = coordinates("theta")
L = 3 * M * R**2 / 4 * dot(theta) ** 2 - M * g * (l - R * theta) * sin(phi)
eom = Eq(dot(theta, 2), 2 * g * sin(phi) / (3 * R))
solution = {theta: theta0 + w0 * t + g * sin(phi) * t**2 / (3 * R)}
a = R * 2 * g * sin(phi) / (3 * R)  # the centre: y = R*theta, so a = R*theta''
