from lagrade.answer import *

m, g, l = parameters("m g l")
x0, y0, vx0, vy0, theta0 = symbols("x0 y0 vx0 vy0 theta0")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
H_a = (p_x**2 + p_y**2)/(2*m) + m*g*y
hamilton_a = [Eq(dot(x), p_x/m), Eq(dot(y), p_y/m), Eq(p_x.diff(t), 0), Eq(p_y.diff(t), -m*g)]
solution_a = {x: x0 + vx0*t, y: y0 + vy0*t - g*t**2/2}
theta = coordinates("theta")
p_theta = momenta("p_theta")
H_b = p_theta**2/(2*m*l**2) - m*g*l*cos(theta)
hamilton_b = [Eq(dot(theta), p_theta/(m*l**2)), Eq(p_theta.diff(t), -m*g*l*sin(theta))]
solution_b = {theta: theta0*cos(sqrt(g/l)*t)}
# motion_b (added when issue 33 asked the exact motion): the pendulum from rest at theta0 = 2, l = 1, g = 9.81,
# Hamilton's equations integrated numerically, to 6 digits
motion_b = {0: 2.000000, 0.4: 1.260090, 0.8: -0.684005, 1.2: -1.920723, 1.6: -1.675226, 2: 0.003146, 2.4: 1.678172, 2.8: 1.919285, 3.2: 0.678230, 3.6: -1.264576, 4: -1.999994}
