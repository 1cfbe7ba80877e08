# Conserved quantities written with the momenta as plain symbols (p_X, ..., and H for the energy).
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, Z, r, theta = coordinates("X Y Z r theta")
p_X, p_Y, p_Z, p_r, p_theta = symbols("p_X p_Y p_Z p_r p_theta")
M = m1 + m2
mu = m1 * m2 / M
dof = 5
H = (p_X**2 + p_Y**2 + p_Z**2) / (2 * M) + p_r**2 / (2 * mu) + p_theta**2 / (2 * mu * r**2) + k * (r - l0)**2 / 2
P = momenta("p_X p_Y p_Z p_r p_theta")
hamilton = [Eq(X.diff(t), P[0] / M), Eq(Y.diff(t), P[1] / M), Eq(Z.diff(t), P[2] / M),
            Eq(r.diff(t), P[3] / mu), Eq(theta.diff(t), P[4] / (mu * r**2)),
            P[0].diff(t), P[1].diff(t), P[2].diff(t),
            Eq(P[3].diff(t), P[4]**2 / (mu * r**3) - k * (r - l0)), P[4].diff(t)]
cyclic = ["X", "Y", "Z", "theta"]
conserved = [p_X, p_Y, p_Z, p_theta, H]
