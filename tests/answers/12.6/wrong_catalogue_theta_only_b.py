# expect: Q_a=missing, dW_a=missing, Q_b=correct, dW_b=correct, delta=correct
# The catalogue's names with theta: Q = {"theta": R*F_t}, dW = R*F_t*delta_theta, F_t = -F_x sin(theta) + F_y cos(theta).
from lagrade.answer import *

m, R, F_x, F_y = parameters("m R F_x F_y")
theta = coordinates("theta")
delta_theta = symbols("delta_theta")
x, y = R * cos(theta), R * sin(theta)
delta = {"x": diff(x, theta) * delta_theta, "y": diff(y, theta) * delta_theta}
dW = F_x * delta["x"] + F_y * delta["y"]
Q = {theta: diff(dW, delta_theta)}
