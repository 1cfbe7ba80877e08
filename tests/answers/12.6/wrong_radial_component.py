# expect: Q_a=incorrect, dW_a=incorrect, Q_b=incorrect, dW_b=incorrect, delta=incorrect
# The radial component of F used instead of the tangential one (displacements along the radius).
from sympy import symbols, sin, cos

R, F_x, F_y, s, theta = symbols("R F_x F_y s theta")
delta_s, delta_theta = symbols("delta_s delta_theta")
Q_a = {"s": F_x * cos(s / R) + F_y * sin(s / R)}
dW_a = Q_a["s"] * delta_s
Q_b = {"theta": R * (F_x * cos(theta) + F_y * sin(theta))}
dW_b = Q_b["theta"] * delta_theta
delta = {"x": R * cos(theta) * delta_theta, "y": R * sin(theta) * delta_theta}
