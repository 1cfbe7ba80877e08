# expect: H_a=incorrect, hamilton_a=partial, solution_a=partial, H_b=correct, hamilton_b=correct, solution_b=correct
# y measured up but V = -m*g*y: gravity pulls the projectile upward.
from lagrade.answer import *

m, g, l = parameters("m g l")
x0, y0, vx0, vy0, theta0 = symbols("x0 y0 vx0 vy0 theta0")
x, y, theta = coordinates("x y theta")
p_x, p_y, p_theta = momenta("p_x p_y p_theta")

H_a = (p_x**2 + p_y**2) / (2 * m) - m * g * y
hamilton_a = [Eq(dot(x), p_x / m), Eq(dot(y), p_y / m), Eq(dot(p_x), 0), Eq(dot(p_y), m * g)]
solution_a = {"x": x0 + vx0 * t, "y": y0 + vy0 * t + g * t**2 / 2}
H_b = p_theta**2 / (2 * m * l**2) - m * g * l * cos(theta)
hamilton_b = [Eq(dot(theta), p_theta / (m * l**2)), Eq(dot(p_theta), -m * g * l * sin(theta))]
solution_b = {"theta": theta0 * cos(sqrt(g / l) * t)}
