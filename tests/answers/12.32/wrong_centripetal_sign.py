# expect: R_r=incorrect, R_theta=correct, R_z=correct
# Centripetal term with the wrong sign (outward "centrifugal" force added to the reaction).
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta = coordinates("theta")
R_r = c * a + m * a * dot(theta) ** 2
R_theta = -c * a * k**2 * theta / (a**2 + k**2)
R_z = c * a**2 * k * theta / (a**2 + k**2)
