# Written with lagrade.answer helpers; H with a constant added, Hamilton's equations scaled and reordered,
# the small-amplitude solution as a sum of exponentials.
from lagrade.answer import *

m, g, l = parameters("m g l")
x0, y0, vx0, vy0, theta0 = symbols("x0 y0 vx0 vy0 theta0")
x, y, theta = coordinates("x y theta")
p_x, p_y, p_theta = momenta("p_x p_y p_theta")

H_a = (p_x**2 + p_y**2) / (2 * m) + m * g * (y - 5)
hamilton_a = [Eq(2 * p_y.diff(t), -2 * m * g), Eq(p_x.diff(t), 0), Eq(p_y, m * dot(y)), Eq(p_x, m * dot(x))]
solution_a = {x: x0 + vx0 * t, y: y0 + vy0 * t - g * t**2 / 2}

H_b = p_theta**2 / (2 * m * l**2) + 2 * m * g * l * sin(theta / 2) ** 2 - m * g * l
hamilton_b = [m * l**2 * dot(theta) - p_theta, dot(p_theta) + m * g * l * sin(theta)]
w = sqrt(g / l)
solution_b = {theta: theta0 * (exp(I * w * t) + exp(-I * w * t)) / 2}
# (b) the pendulum's motion from rest at theta0 = 2, integrated numerically, to 6 digits
motion_b = {"t": [0, 0.2, 0.4, 0.6, 0.8, 1, 1.2, 1.4, 1.6, 1.8, 2, 2.2, 2.4, 2.6, 2.8, 3, 3.2, 3.4, 3.6, 3.8, 4],
            "theta": [2.000000, 1.819350, 1.260090, 0.347850, -0.684005, -1.491035, -1.920723, -1.979910, -1.675226, -0.987405, 0.003146, 0.992599, 1.678172, 1.980619, 1.919285, 1.487306, 0.678230, -0.354005, -1.264576, -1.821524, -1.999994]}
