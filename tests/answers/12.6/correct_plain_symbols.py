# Coordinates as plain symbols; Q_theta written as R*F_t with F_t from a rotation; dW from dx, dy.
from sympy import symbols, sin, cos, expand_trig

R, F_x, F_y, s, theta = symbols("R F_x F_y s theta")
delta_s, delta_theta = symbols("delta_s delta_theta")
Q_a = {"s": F_y * cos(s / R) - F_x * sin(s / R)}
dW_a = (F_x * (-sin(s / R)) + F_y * cos(s / R)) * delta_s
Q_b = {"theta": -R * F_x * sin(theta) + R * F_y * cos(theta)}
dW_b = F_x * (-R * sin(theta) * delta_theta) + F_y * (R * cos(theta) * delta_theta)
delta = {"x": -R * sin(theta) * delta_theta, "y": R * cos(theta) * delta_theta}
