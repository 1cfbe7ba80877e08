# The catalogue's planar formulation: X, Y, r, theta and their momenta (M = m1 + m2, mu = m1*m2/M); cyclic
# coordinates and conserved quantities of that formulation; 6 degrees of freedom in space.
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, r, theta = coordinates("X Y r theta")
p_X, p_Y, p_r, p_theta = momenta("p_X p_Y p_r p_theta")
M = m1 + m2
mu = m1 * m2 / M
dof = 6
H = (p_X**2 + p_Y**2) / (2 * M) + (p_r**2 + p_theta**2 / r**2) / (2 * mu) + k * (r - l0) ** 2 / 2
hamilton = [
    Eq(dot(X), p_X / M), Eq(dot(Y), p_Y / M), Eq(dot(r), p_r / mu), Eq(dot(theta), p_theta / (mu * r**2)),
    Eq(dot(p_X), 0), Eq(dot(p_Y), 0), Eq(dot(p_r), p_theta**2 / (mu * r**3) - k * (r - l0)), Eq(dot(p_theta), 0),
]
cyclic = [X, Y, theta]
conserved = [p_X, p_Y, p_theta, H]
