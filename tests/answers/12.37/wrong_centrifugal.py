# expect: H=incorrect, hamilton=partial, conserved=partial
# The rotational term p_theta^2/(2 mu r^2) left out of H (so p_r' misses the centrifugal term and theta' is 0);
# and the angular momentum written mu r theta' (one r short), which is not conserved; energy not listed.
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, Z, r, theta = coordinates("X Y Z r theta")
p_X, p_Y, p_Z, p_r, p_theta = momenta("p_X p_Y p_Z p_r p_theta")
M = m1 + m2
mu = m1 * m2 / M
dof = 5
H = (p_X**2 + p_Y**2 + p_Z**2) / (2 * M) + p_r**2 / (2 * mu) + k * (r - l0)**2 / 2
hamilton = [
    Eq(X.diff(t), p_X / M), Eq(Y.diff(t), p_Y / M), Eq(Z.diff(t), p_Z / M),
    Eq(r.diff(t), p_r / mu), Eq(theta.diff(t), 0),
    Eq(p_X.diff(t), 0), Eq(p_Y.diff(t), 0), Eq(p_Z.diff(t), 0),
    Eq(p_r.diff(t), -k * (r - l0)), Eq(p_theta.diff(t), 0),
]
cyclic = ["X", "Y", "Z", "theta"]
conserved = [M * dot(X), M * dot(Y), M * dot(Z), mu * r * dot(theta)]
