# expect: hamilton=correct, cyclic=partial
# Right planar Hamilton's equations, so cyclic is judged in the planar formulation: Z is no coordinate there,
# and r appears in H.
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, r, theta = coordinates("X Y r theta")
p_X, p_Y, p_r, p_theta = momenta("p_X p_Y p_r p_theta")
M = m1 + m2
mu = m1 * m2 / M
hamilton = [
    Eq(dot(X), p_X / M), Eq(dot(Y), p_Y / M), Eq(dot(r), p_r / mu), Eq(dot(theta), p_theta / (mu * r**2)),
    Eq(dot(p_X), 0), Eq(dot(p_Y), 0), Eq(dot(p_r), p_theta**2 / (mu * r**3) - k * (r - l0)), Eq(dot(p_theta), 0),
]
cyclic = ["X", "Y", "Z", "theta", "r"]
