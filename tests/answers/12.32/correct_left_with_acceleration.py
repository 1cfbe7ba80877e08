# expect: R_r=correct, R_theta=correct, R_z=correct
# Components left in terms of the accelerations (Newton's law along each direction minus the real force):
# the statement says "theta'' may be used", so they are evaluated on the true motion (issue 44).
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta, z, r = coordinates("theta z r")
R_r = m * (diff(r, t, 2) - r * dot(theta) ** 2) + c * r
R_theta = m * a * dot(theta, 2)
R_z = m * diff(z, t, 2) + c * z
