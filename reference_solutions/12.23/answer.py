"""Problem 12.23: a ladder (uniform rod M, length l) slides on a smooth wall and floor.

Centre of mass at (l/2 cos(theta), l/2 sin(theta)), speed l theta'/2; rotation about the centre I = M l**2/12:
T = M l**2 theta'**2/8 + M l**2 theta'**2/24 = M l**2 theta'**2/6,  V = M g l sin(theta)/2.
Lagrange: M l**2 theta''/3 + M g l cos(theta)/2 = 0  ->  theta'' = -3 g cos(theta)/(2 l).
Wall force = M x_cm'' with x_cm = l cos(theta)/2:
N_w = -M l/2 (sin(theta) theta'' + cos(theta) theta'**2) = M cos(theta)(3 g sin(theta)/4 - l theta'**2/2).
Released from rest at theta0: theta'**2 = 3 g (sin(theta0) - sin(theta))/l, so
N_w = 3 M g cos(theta)(3 sin(theta) - 2 sin(theta0))/4, zero when sin(theta) = 2 sin(theta0)/3.
"""
from sympy import Eq, Function, asin, cos, diff, sin, symbols

t = symbols("t")
M, l, g, theta0 = symbols("M l g theta0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)

L = M * l**2 * thd**2 / 6 - M * g * l * sin(theta) / 2
eom = [Eq(theta.diff(t, 2), -3 * g * cos(theta) / (2 * l))]

x_cm = l * cos(theta) / 2
N_w = M * diff(x_cm, t, 2).subs(theta.diff(t, 2), -3 * g * cos(theta) / (2 * l))

w = symbols("w")
N_rest = N_w.subs(thd, w).subs(w**2, 3 * g * (sin(theta0) - sin(theta)) / l)
leave_angle = asin(2 * sin(theta0) / 3)
