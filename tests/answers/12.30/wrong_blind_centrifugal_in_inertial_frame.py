# expect: eom_xy=incorrect, eom=correct, N=correct
from lagrade.answer import *

m, omega = parameters("m omega")
x, y = coordinates("x y")
r, theta = coordinates("r theta")
# added a centrifugal force although x, y are inertial coordinates
eom_xy = [Eq(cos(omega*t)*dot(x, 2) + sin(omega*t)*dot(y, 2), omega**2*(x*cos(omega*t) + y*sin(omega*t))),
          Eq(y, x*tan(omega*t))]
eom = [Eq(dot(r, 2), omega**2*r)]
lam = 2*m*omega*r*dot(r)
N = 2*m*omega*dot(r)
