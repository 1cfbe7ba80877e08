# expect: Q_a=incorrect, dW_a=incorrect, Q_b=missing, dW_b=missing
# Catalogue names, arc length s: the factor R of the torque Q_theta kept although delta_s is a length.
from lagrade.answer import *

m, R, F_x, F_y = parameters("m R F_x F_y")
s = coordinates("s")
delta_s = symbols("delta_s")
Q = {"s": R * (-F_x * sin(s / R) + F_y * cos(s / R))}
dW = Q["s"] * delta_s
