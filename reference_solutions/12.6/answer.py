"""Problem 12.6: particle on a circle of radius R under a force F = (F_x, F_y).

x = R cos(theta), y = R sin(theta): dx = -R sin(theta) dtheta, dy = R cos(theta) dtheta.
dW = F_x dx + F_y dy = R (-F_x sin(theta) + F_y cos(theta)) dtheta = F_t R dtheta.
With s = R theta: dtheta = ds / R, so dW = F_t ds: Q_s = F_t (a force), Q_theta = R F_t (a torque).
"""
from sympy import Function, cos, sin, symbols

t = symbols("t")
R, F_x, F_y = symbols("R F_x F_y")
s = Function("s")(t)
theta = Function("theta")(t)
delta_s, delta_theta = symbols("delta_s delta_theta")

F_t_s = -F_x * sin(s / R) + F_y * cos(s / R)          # tangential component, at theta = s/R
Q_a = {"s": F_t_s}            # (a): the arc length s (a force)
dW_a = F_t_s * delta_s

delta = {"x": -R * sin(theta) * delta_theta, "y": R * cos(theta) * delta_theta}
dW_b = F_x * delta["x"] + F_y * delta["y"]   # (b), the catalogue's Q and dW: theta (Q a torque)
Q_b = {"theta": R * (-F_x * sin(theta) + F_y * cos(theta))}
