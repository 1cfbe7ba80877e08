"""Problem 12.37: two masses on a spring, rotating in a plane, centre of mass free in space.

Centre of mass R = (X, Y, Z), total mass M = m1 + m2; relative vector of length r at angle theta in
the plane of rotation, reduced mass mu = m1 m2/M:
  L = M (X'^2 + Y'^2 + Z'^2)/2 + mu (r'^2 + r^2 theta'^2)/2 - k (r - l0)^2/2.
(a) two point masses free in space: 2 x 3 = 6 degrees of freedom (3 for R, r and two angles of the
  relative vector); 5 (X, Y, Z, r, theta) if the relative motion keeps one fixed plane, also accepted.
(b) p_X = M X', ..., p_r = mu r', p_theta = mu r^2 theta';
  H = (p_X^2 + p_Y^2 + p_Z^2)/(2M) + p_r^2/(2 mu) + p_theta^2/(2 mu r^2) + k (r - l0)^2/2.
(c) X, Y, Z, theta do not appear in H: the total linear momentum and the angular momentum
  p_theta = mu r^2 theta' are conserved; t does not appear either: H = E is conserved.
The planar formulation (X, Y, r, theta: the catalogue's) is accepted too for H, hamilton, cyclic
(then X, Y, theta) and conserved; cyclic and conserved follow the formulation of hamilton.
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m1, m2, k, l0 = symbols("m1 m2 k l0", positive=True)
M = m1 + m2
mu = m1 * m2 / M
X, Y, Z, r, theta = (Function(n)(t) for n in ("X", "Y", "Z", "r", "theta"))
p_X, p_Y, p_Z, p_r, p_theta = (Function(n)(t) for n in ("p_X", "p_Y", "p_Z", "p_r", "p_theta"))

dof = 6
H = (p_X**2 + p_Y**2 + p_Z**2) / (2 * M) + p_r**2 / (2 * mu) + p_theta**2 / (2 * mu * r**2) + k * (r - l0) ** 2 / 2
hamilton = [
    Eq(X.diff(t), p_X / M), Eq(Y.diff(t), p_Y / M), Eq(Z.diff(t), p_Z / M),
    Eq(r.diff(t), p_r / mu), Eq(theta.diff(t), p_theta / (mu * r**2)),
    Eq(p_X.diff(t), 0), Eq(p_Y.diff(t), 0), Eq(p_Z.diff(t), 0),
    Eq(p_r.diff(t), p_theta**2 / (mu * r**3) - k * (r - l0)),
    Eq(p_theta.diff(t), 0),
]
cyclic = ["X", "Y", "Z", "theta"]
Xd, Yd, Zd, rd, thd = (q.diff(t) for q in (X, Y, Z, r, theta))
E = M * (Xd**2 + Yd**2 + Zd**2) / 2 + mu * (rd**2 + r**2 * thd**2) / 2 + k * (r - l0) ** 2 / 2
conserved = [M * Xd, M * Yd, M * Zd, mu * r**2 * thd, E]
