"""Problem 12.30: bead on a smooth straight wire turning at constant omega about a perpendicular axis through O.

Cartesian: L = m/2 (x'^2 + y'^2), constraint f = x sin(wt) - y cos(wt) = 0 (multiplier mu):
  m x'' = mu sin(wt),  m y'' = -mu cos(wt)
  eliminating mu (dot with the wire direction (cos wt, sin wt)): x'' cos(wt) + y'' sin(wt) = 0.
Polar: L = m/2 (r'^2 + r^2 theta'^2), constraint theta = w t (multiplier lam):
  r:     m r'' - m r theta'^2 = 0  ->  r'' = w^2 r
  theta: d/dt(m r^2 theta') = lam  ->  lam = 2 m w r r'  (torque of the wire about the axis)
  normal force N = lam / r = 2 m w r' (perpendicular to the wire, in the sense of rotation); mu = -N.
"""
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)

x, y = Function("x")(t), Function("y")(t)
# the equation of motion along the wire (y = x tan(wt) is the constraint itself)
eom_xy = [Eq(x.diff(t, 2) * cos(omega * t) + y.diff(t, 2) * sin(omega * t), 0)]

r = Function("r")(t)
eom = [Eq(r.diff(t, 2), omega**2 * r)]
lam = 2 * m * omega * r * r.diff(t)
N = 2 * m * omega * r.diff(t)
