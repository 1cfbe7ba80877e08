# Written with the force's magnitude and direction in the xy plane: F_x = F cos(alpha), F_y = F sin(alpha),
# so Q_r = F cos(alpha - theta) and Q_theta = r F sin(alpha - theta) (trig identities of the reference).
from sympy import atan2, cos, sin, sqrt, symbols

F_x, F_y, F_z = symbols("F_x F_y F_z")
r, theta = symbols("r theta")
delta_r, delta_theta, delta_z = symbols("delta_r delta_theta delta_z")

F = sqrt(F_x**2 + F_y**2)
alpha = atan2(F_y, F_x)
Q = {"r": F * cos(alpha - theta), "theta": r * F * sin(alpha - theta), "z": F_z}
dW = Q["r"] * delta_r + Q["theta"] * delta_theta + Q["z"] * delta_z
delta = {"x": cos(theta) * delta_r - r * sin(theta) * delta_theta,
         "y": sin(theta) * delta_r + r * cos(theta) * delta_theta,
         "z": delta_z}
