# expect: delta=correct, dW=incorrect, Q=partial
# Q_r taken as F_x and Q_theta as F_y: Cartesian components are not the generalized forces of r and theta.
from sympy import cos, sin, symbols

F_x, F_y, F_z = symbols("F_x F_y F_z")
r, theta = symbols("r theta")
delta_r, delta_theta, delta_z = symbols("delta_r delta_theta delta_z")

delta = {"x": cos(theta) * delta_r - r * sin(theta) * delta_theta,
         "y": sin(theta) * delta_r + r * cos(theta) * delta_theta,
         "z": delta_z}
Q = {"r": F_x, "theta": F_y, "z": F_z}
dW = F_x * delta_r + F_y * delta_theta + F_z * delta_z
