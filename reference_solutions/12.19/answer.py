"""Problem 12.19: elliptic coordinates x = A cosh(u) cos(v), y = A sinh(u) sin(v).

x' = A (sinh u cos v u' - cosh u sin v v'),  y' = A (cosh u sin v u' + sinh u cos v v');
the cross terms cancel and sinh**2 u cos**2 v + cosh**2 u sin**2 v = sinh**2 u + sin**2 v, so
T = m A**2 (sinh**2 u + sin**2 v)(u'**2 + v'**2)/2.  Q_k = F . dr/dq_k.
"""
from sympy import Eq, Function, cos, cosh, diff, sin, sinh, symbols

t = symbols("t")
m, A, F_x, F_y = symbols("m A F_x F_y")
u, v = Function("u")(t), Function("v")(t)
ud, vd = u.diff(t), v.diff(t)

x = A * cosh(u) * cos(v)
y = A * sinh(u) * sin(v)
h2 = sinh(u) ** 2 + sin(v) ** 2
T = m * A**2 * h2 * (ud**2 + vd**2) / 2
L = T

# d/dt(m A**2 h2 u') - m A**2 sinh(u) cosh(u) (u'**2 + v'**2) = 0, and the same for v with sin(v) cos(v)
eom = [
    Eq(h2 * u.diff(t, 2) + (sinh(2 * u) * ud + sin(2 * v) * vd) * ud - sinh(2 * u) * (ud**2 + vd**2) / 2, 0),
    Eq(h2 * v.diff(t, 2) + (sinh(2 * u) * ud + sin(2 * v) * vd) * vd - sin(2 * v) * (ud**2 + vd**2) / 2, 0),
]

Q = {"u": F_x * diff(x, u) + F_y * diff(y, u), "v": F_x * diff(x, v) + F_y * diff(y, v)}
# Also accepted for eom (the catalogue's form): the same left-hand sides equal to generalized forces Q_u, Q_v
# left as symbols, i.e. m*A**2*(h2*u'' + ...) = Q_u and m*A**2*(h2*v'' + ...) = Q_v (system "forced").
