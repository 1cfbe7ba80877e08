# expect: eom_xy=correct, eom=incorrect, N=incorrect
# Centrifugal term with the wrong sign (r'' = -omega**2 r, as if the wire pulled the bead in), and the
# wire's force taken as the centripetal force m omega**2 r.
from lagrade.answer import *

m, omega = parameters("m omega")
x, y, r = coordinates("x y r")
eom_xy = [Eq(dot(x, 2) * cos(omega * t) + dot(y, 2) * sin(omega * t), 0)]
eom = [Eq(dot(r, 2), -omega**2 * r)]
lam = m * omega**2 * r**2
N = m * omega**2 * r
