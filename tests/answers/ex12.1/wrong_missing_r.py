# expect: delta=partial, dW=incorrect, Q=partial
# The azimuthal displacement taken as delta_theta instead of r*delta_theta (dx/dtheta written -sin(theta)).
from sympy import cos, sin, symbols

F_x, F_y, F_z = symbols("F_x F_y F_z")
r, theta = symbols("r theta")
delta_r, delta_theta, delta_z = symbols("delta_r delta_theta delta_z")

delta = {"x": cos(theta) * delta_r - sin(theta) * delta_theta,
         "y": sin(theta) * delta_r + cos(theta) * delta_theta,
         "z": delta_z}
dW = F_x * delta["x"] + F_y * delta["y"] + F_z * delta["z"]
Q = {"r": F_x * cos(theta) + F_y * sin(theta), "theta": F_y * cos(theta) - F_x * sin(theta), "z": F_z}
