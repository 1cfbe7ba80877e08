# expect: Q_a=incorrect, dW_a=incorrect, Q_b=incorrect, dW_b=incorrect, delta=correct
# The factors R swapped: Q_s given as a torque and Q_theta as a force.
from sympy import symbols, sin, cos

R, F_x, F_y, s, theta = symbols("R F_x F_y s theta")
delta_s, delta_theta = symbols("delta_s delta_theta")
Q_a = {"s": R * (-F_x * sin(s / R) + F_y * cos(s / R))}
dW_a = Q_a["s"] * delta_s
Q_b = {"theta": -F_x * sin(theta) + F_y * cos(theta)}
dW_b = Q_b["theta"] * delta_theta
delta = {"x": -R * sin(theta) * delta_theta, "y": R * cos(theta) * delta_theta}
