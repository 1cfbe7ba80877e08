# expect: eom_xy=correct, eom=incorrect, N=correct
from lagrade.answer import *

m, omega = parameters("m omega")
x, y = coordinates("x y")
r, theta = coordinates("r theta")
eom_xy = [Eq(cos(omega*t)*dot(x, 2) + sin(omega*t)*dot(y, 2), 0), Eq(y, x*tan(omega*t))]
eom = [Eq(dot(r, 2), -omega**2*r)]           # centrifugal term with the wrong sign
lam = 2*m*omega*r*dot(r)
N = 2*m*omega*dot(r)
