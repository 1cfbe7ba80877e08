# expect: L_a=correct, eom_a=correct, L_b=correct, eom_b=partial
# (b) d/dt(cos(theta)*theta') differentiated without the -sin(theta)*theta'**2 term in the X equation.
from lagrade.answer import *

m, M, g, R = parameters("m M g R")
alpha = Symbol("theta")  # (a): the incline angle is the parameter theta
x1, x2, X, theta = coordinates("x1 x2 X theta")
L_a = (M + m) * dot(x1) ** 2 / 2 + m * dot(x2) ** 2 / 2 + m * cos(alpha) * dot(x1) * dot(x2) + m * g * x2 * sin(alpha)
eom_a = [Eq((M + m) * dot(x1, 2) + m * cos(alpha) * dot(x2, 2), 0),
         Eq(dot(x2, 2) + cos(alpha) * dot(x1, 2), g * sin(alpha))]
L_b = (M + m) * dot(X) ** 2 / 2 + m * R * cos(theta) * dot(X) * dot(theta) + m * R**2 * dot(theta) ** 2 / 2 - m * g * R * cos(theta)
eom_b = [Eq((M + m) * dot(X, 2) + m * R * cos(theta) * dot(theta, 2), 0),
         Eq(R * dot(theta, 2) + cos(theta) * dot(X, 2), g * sin(theta))]
