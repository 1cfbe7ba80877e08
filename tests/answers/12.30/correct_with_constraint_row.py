# The Cartesian equation along the wire plus the constraint equation itself, as a careful student lists them
# (after y = x*tan(wt) is substituted the constraint row is x*sin(wt) - x*tan(wt)*cos(wt), zero only up to rounding).
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
