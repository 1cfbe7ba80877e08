"""Exercise 12.1: virtual displacements and generalized forces in cylindrical coordinates.

x = r cos(theta), y = r sin(theta), z = z.
delta x = dx/dr delta r + dx/dtheta delta theta = cos(theta) delta r - r sin(theta) delta theta
delta y = sin(theta) delta r + r cos(theta) delta theta,   delta z = delta z.
dW = F . delta r = Q_r delta r + Q_theta delta theta + Q_z delta z, so
Q_r = F_x cos(theta) + F_y sin(theta)              (the radial component F_r, a force)
Q_theta = r (F_y cos(theta) - F_x sin(theta))      (r F_theta, the torque about the z axis)
Q_z = F_z.
"""
from sympy import cos, expand, sin, symbols

F_x, F_y, F_z = symbols("F_x F_y F_z")
r, theta = symbols("r theta", positive=True)
delta_r, delta_theta, delta_z = symbols("delta_r delta_theta delta_z")

x, y = r * cos(theta), r * sin(theta)
dx = x.diff(r) * delta_r + x.diff(theta) * delta_theta
dy = y.diff(r) * delta_r + y.diff(theta) * delta_theta
dz = delta_z
delta = {"x": dx, "y": dy, "z": dz}

dW = expand(F_x * dx + F_y * dy + F_z * dz)
Q = {"r": dW.coeff(delta_r), "theta": dW.coeff(delta_theta), "z": dW.coeff(delta_z)}
