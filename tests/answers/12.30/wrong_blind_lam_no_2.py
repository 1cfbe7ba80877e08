# expect: eom_xy=correct, eom=correct, N=incorrect
from lagrade.answer import *

m, omega = parameters("m omega")
x, y = coordinates("x y")
r, theta = coordinates("r theta")
eom_xy = [Eq(cos(omega*t)*dot(x, 2) + sin(omega*t)*dot(y, 2), 0), Eq(y, x*tan(omega*t))]
eom = [dot(r, 2) - omega**2*r]
lam = m*omega*r*dot(r)          # d/dt(m r^2 omega) taken as m r r' omega
N = m*omega*dot(r)
