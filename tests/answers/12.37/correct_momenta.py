# Equivalent forms: conserved quantities written with momenta (the energy as H), cyclic given as the
# coordinates themselves, Hamilton's equations multiplied out and reordered, dof as a sympy Integer.
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, Z, r, theta = coordinates("X Y Z r theta")
p_X, p_Y, p_Z, p_r, p_theta = momenta("p_X p_Y p_Z p_r p_theta")
M = m1 + m2
dof = Integer(5)
H = (p_X**2 + p_Y**2 + p_Z**2) / (2 * M) + M * (p_r**2 + p_theta**2 / r**2) / (2 * m1 * m2) + k * (r - l0)**2 / 2
hamilton = [
    Eq(p_theta.diff(t), 0), Eq(p_Z.diff(t), 0), Eq(p_Y.diff(t), 0), Eq(p_X.diff(t), 0),
    Eq(m1 * m2 * r**3 * p_r.diff(t), M * p_theta**2 - m1 * m2 * k * r**3 * (r - l0)),
    Eq(m1 * m2 * r.diff(t), M * p_r), Eq(m1 * m2 * r**2 * theta.diff(t), M * p_theta),
    Eq(M * X.diff(t), p_X), Eq(M * Y.diff(t), p_Y), Eq(M * Z.diff(t), p_Z),
]
cyclic = [theta, X, Y, Z]
conserved = [p_X, p_Y, p_Z, p_theta, H]
