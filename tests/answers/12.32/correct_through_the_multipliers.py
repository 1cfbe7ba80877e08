# The forces through the multipliers: R_theta = -k*R_z/a (normal to the wire), R_r = a*(c - m*theta'^2).
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta = coordinates("theta")
R_z = c * a**2 * k * theta / (a**2 + k**2)
R_theta = -k * R_z / a
R_r = a * (c - m * dot(theta) ** 2)
