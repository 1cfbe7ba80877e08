# expect: L_a=incorrect, eom_a=incorrect, L_b=incorrect, eom_b=incorrect
# The wedge's motion ignored in the particle's kinetic energy (no cross terms).
from lagrade.answer import *

m, M, g, R = parameters("m M g R")
alpha = Symbol("theta")  # (a): the incline angle is the parameter theta
x1, x2, X, theta = coordinates("x1 x2 X theta")
L_a = M * dot(x1) ** 2 / 2 + m * dot(x2) ** 2 / 2 + m * g * x2 * sin(alpha)
eom_a = [Eq(dot(x1, 2), 0), Eq(dot(x2, 2), g * sin(alpha))]
L_b = M * dot(X) ** 2 / 2 + m * R**2 * dot(theta) ** 2 / 2 - m * g * R * cos(theta)
eom_b = [Eq(dot(X, 2), 0), Eq(R * dot(theta, 2), g * sin(theta))]
