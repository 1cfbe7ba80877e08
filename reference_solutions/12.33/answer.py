"""Problem 12.33: a small smooth sphere sliding off a large fixed sphere.

Centre of the small sphere at distance rho from the centre of the large one, angle theta from the
upward vertical: T = m (rho'^2 + rho^2 theta'^2)/2, V = m g rho cos(theta), constraint rho = R + r_s.
rho-equation with the multiplier (the outward reaction): m rho'' - m rho theta'^2 + m g cos(theta) = lam,
so with rho'' = 0:  lam = m g cos(theta) - m (R + r_s) theta'^2.
theta-equation: (R + r_s) theta'' = g sin(theta).
From rest at the top: (R + r_s) theta'^2 = 2 g (1 - cos(theta)), so N = m g (3 cos(theta) - 2),
which vanishes at cos(theta) = 2/3 (independent of the radii).
"""
from sympy import Eq, Function, Rational, acos, cos, sin, symbols

t = symbols("t")
m, R, r_s, g = symbols("m R r_s g", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

b = R + r_s  # distance between the centres while in contact
L = m * b**2 * thd**2 / 2 - m * g * b * cos(theta)
eom = [Eq(b * theta.diff(t, 2), g * sin(theta))]

lam = m * g * cos(theta) - m * b * thd**2
N = m * g * (3 * cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
