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
