# expect: delta=correct, dW=incorrect, Q=partial
# Sign slip in dx/dtheta (+r sin(theta)): the torque Q_theta comes out with the wrong sign of the F_x term.
from sympy import cos, sin, symbols

F_x, F_y, F_z = symbols("F_x F_y F_z")
r, theta = symbols("r theta")
delta_r, delta_theta, delta_z = symbols("delta_r delta_theta delta_z")

delta = {"x": cos(theta) * delta_r - r * sin(theta) * delta_theta,
         "y": sin(theta) * delta_r + r * cos(theta) * delta_theta,
         "z": delta_z}
Q = {"r": F_x * cos(theta) + F_y * sin(theta), "theta": r * (F_x * sin(theta) + F_y * cos(theta)), "z": F_z}
dW = Q["r"] * delta_r + Q["theta"] * delta_theta + Q["z"] * delta_z
