"""Problem 12.21: u = ln(r/a) - theta cot(phi), v = ln(r/a) + theta tan(phi) (orthogonal spirals).

Let s = sin(phi), c = cos(phi), rho = ln(r/a).  v - u = theta (tan + cot) = theta/(s c), so
theta = (v - u) s c and rho = u + theta cot = u s**2 + v c**2.
T = m (r'**2 + r**2 theta'**2)/2 = m r**2 (rho'**2 + theta'**2)/2 = m r**2 (s**2 u'**2 + c**2 v'**2)/2.
Q_k = F_r dr/dq_k + F_theta r dtheta/dq_k:  dr/du = r s**2, r dtheta/du = -r s c, dr/dv = r c**2, r dtheta/dv = r s c.
Free motion: a straight line; from (b, 0) with speed w along +y: x = b, y = w t.
"""
from sympy import Eq, Function, atan, cos, cot, exp, log, sin, sqrt, symbols, tan

t = symbols("t")
m, a, phi, b, w = symbols("m a phi b w", positive=True)
F_r, F_theta = symbols("F_r F_theta")
u, v = Function("u")(t), Function("v")(t)
ud, vd = u.diff(t), v.diff(t)
s, c = sin(phi), cos(phi)

R = a * exp(u * s**2 + v * c**2)          # r in terms of u, v
TH = (v - u) * s * c                      # theta
T = m * R**2 * (s**2 * ud**2 + c**2 * vd**2) / 2
L = T

Q = {"u": F_r * R.diff(u) + F_theta * R * TH.diff(u), "v": F_r * R.diff(v) + F_theta * R * TH.diff(v)}

# dL/du = 2 s**2 L, dL/du' = m R**2 s**2 u'; R' = R (s**2 u' + c**2 v')
eom = [
    Eq(u.diff(t, 2) + s**2 * ud**2 + 2 * c**2 * ud * vd - c**2 * vd**2, 0),
    Eq(v.diff(t, 2) + c**2 * vd**2 + 2 * s**2 * ud * vd - s**2 * ud**2, 0),
]

r_t = sqrt(b**2 + w**2 * t**2)
th_t = atan(w * t / b)
solution = {"u": log(r_t / a) - th_t * cot(phi), "v": log(r_t / a) + th_t * tan(phi)}
