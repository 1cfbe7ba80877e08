# Cartesian: both Newton components with the normal force N = 2 m omega r' written in x, y substituted;
# polar: the theta equation differentiated out and N, lam written with theta'.
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r, theta = coordinates("x y r theta")
c, s = cos(omega * t), sin(omega * t)
N_xy = 2 * m * omega * (dot(x) * c + dot(y) * s)
eom_xy = [Eq(m * dot(x, 2), -N_xy * s), Eq(m * dot(y, 2), N_xy * c)]
eom = [m * dot(r, 2) - m * r * dot(theta) ** 2]
lam = 2 * m * r * dot(r) * dot(theta)
N = 2 * m * dot(r) * dot(theta)
