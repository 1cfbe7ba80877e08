# expect: R_r=invalid, R_theta=invalid, R_z=invalid
# Components left in terms of theta'' and z (Newton's law along each direction minus the real force):
# the accelerations are not solved for, so nothing is (the grader would fill in the true ones).
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta, z, r = coordinates("theta z r")
R_r = m * (diff(r, t, 2) - r * dot(theta) ** 2) + c * r
R_theta = m * a * dot(theta, 2)
R_z = m * diff(z, t, 2) + c * z
