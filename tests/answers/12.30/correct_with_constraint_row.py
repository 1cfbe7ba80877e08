# The Cartesian equation along the wire plus the constraint equation itself, as a careful student lists them.
# ENGINE PROBLEM: the constraint row x*sin(wt) - y*cos(wt) becomes x*sin(wt) - x*tan(wt)*cos(wt) after y is
# substituted; numerically ~1e-16, but the row's own scale is also ~1e-16, so it is judged "does not hold".
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r = coordinates("x y r")
eom_xy = [
    Eq(dot(x, 2) * cos(omega * t) + dot(y, 2) * sin(omega * t), 0),
    Eq(x * sin(omega * t) - y * cos(omega * t), 0),
]
eom = [Eq(dot(r, 2), omega**2 * r)]
lam = 2 * m * omega * r * dot(r)
N = 2 * m * omega * dot(r)
