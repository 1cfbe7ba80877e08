# (a) unsolved Lagrange equations, multiplied through; (b) solved for the accelerations; L_b plus d/dt(X*t).
from lagrade.answer import *

m, M, g, R = parameters("m M g R")
alpha = Symbol("theta")  # (a): the incline angle is the parameter theta
x1, x2, X, theta = coordinates("x1 x2 X theta")
L_a = (M + m) * dot(x1) ** 2 / 2 + m * dot(x2) ** 2 / 2 + m * cos(alpha) * dot(x1) * dot(x2) + m * g * x2 * sin(alpha)
eom_a = [
    2 * ((M + m) * dot(x1, 2) + m * cos(alpha) * dot(x2, 2)),
    Eq(m * dot(x2, 2) + m * cos(alpha) * dot(x1, 2), m * g * sin(alpha)),
]
L_b = ((M + m) * dot(X) ** 2 / 2 + m * R * cos(theta) * dot(X) * dot(theta) + m * R**2 * dot(theta) ** 2 / 2
       - m * g * R * cos(theta) + X + t * dot(X))
D = M + m * sin(theta) ** 2
eom_b = [
    Eq(dot(theta, 2), ((M + m) * g * sin(theta) - m * R * sin(theta) * cos(theta) * dot(theta) ** 2) / (R * D)),
    Eq(dot(X, 2), m * sin(theta) * (R * dot(theta) ** 2 - g * cos(theta)) / D),
]
