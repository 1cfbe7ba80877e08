# expect: dof=correct, H=incorrect, hamilton=partial, cyclic=correct, conserved=partial
# The relative motion given the total mass M instead of the reduced mass mu (H, r' and theta' wrong).
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, Z, r, theta = coordinates("X Y Z r theta")
p_X, p_Y, p_Z, p_r, p_theta = momenta("p_X p_Y p_Z p_r p_theta")
M = m1 + m2
dof = 5
H = (p_X**2 + p_Y**2 + p_Z**2) / (2 * M) + (p_r**2 + p_theta**2 / r**2) / (2 * M) + k * (r - l0)**2 / 2
hamilton = [
    Eq(X.diff(t), p_X / M), Eq(Y.diff(t), p_Y / M), Eq(Z.diff(t), p_Z / M),
    Eq(r.diff(t), p_r / M), Eq(theta.diff(t), p_theta / (M * r**2)),
    Eq(p_X.diff(t), 0), Eq(p_Y.diff(t), 0), Eq(p_Z.diff(t), 0),
    Eq(p_r.diff(t), p_theta**2 / (M * r**3) - k * (r - l0)), Eq(p_theta.diff(t), 0),
]
cyclic = ["X", "Y", "Z", "theta"]
Xd, Yd, Zd, rd, thd = (dot(q) for q in (X, Y, Z, r, theta))
conserved = [M * Xd, M * Yd, M * Zd, M * r**2 * thd,
             M * (Xd**2 + Yd**2 + Zd**2) / 2 + M * (rd**2 + r**2 * thd**2) / 2 + k * (r - l0)**2 / 2]
