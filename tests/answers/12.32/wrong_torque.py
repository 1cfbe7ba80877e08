# expect: R_r=correct, R_theta=incorrect, R_z=correct
# Gave the generalized theta component (a torque, -k*lam2) instead of the force component.
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta = coordinates("theta")
R_r = c * a - m * a * dot(theta) ** 2
R_theta = -c * a**2 * k**2 * theta / (a**2 + k**2)
R_z = c * a**2 * k * theta / (a**2 + k**2)
