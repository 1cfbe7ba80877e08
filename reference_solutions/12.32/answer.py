"""Problem 12.32: reaction of the helix r = a, z = k theta on the bead of 12.31 (F = -c r_vec).

L = m/2 (r'^2 + r^2 theta'^2 + z'^2) - c/2 (r^2 + z^2), constraints f1 = r - a, f2 = z - k theta:
  r:     m r'' - m r theta'^2 + c r = lam1
  theta: m r^2 theta'' + 2 m r r' theta' = -k lam2
  z:     m z'' + c z = lam2
On the wire (r = a, z = k theta): theta'' = -c k^2 theta/(m (a^2 + k^2)), so
  R_r = lam1 = c a - m a theta'^2
  R_z = lam2 = m k theta'' + c k theta = c a^2 k theta/(a^2 + k^2)
  R_theta = -k lam2 / a = m a theta'' = -c a k^2 theta/(a^2 + k^2)   (a R_theta + k R_z = 0: normal to the wire)
"""
from sympy import Function, symbols

t = symbols("t")
m, a, k, c = symbols("m a k c", positive=True)
theta = Function("theta")(t)

R_r = c * a - m * a * theta.diff(t) ** 2
R_theta = -c * a * k**2 * theta / (a**2 + k**2)
R_z = c * a**2 * k * theta / (a**2 + k**2)
