# target: eom
# family: beyond
# expect: no-credit
# why: the z equation multiplied by cos(2*alpha), which vanishes at alpha = pi/4, inside 0 < alpha < pi/2: the equations say nothing about z'' there
from sympy import *

t = symbols("t")
m, g, h, alpha = symbols("m g h alpha", positive=True)
z, phi = Function("z")(t), Function("phi")(t)
zd, phid = z.diff(t), phi.diff(t)
eom = [
    Eq(cos(2*alpha)*m*z.diff(t, 2)/cos(alpha)**2, cos(2*alpha)*(m*z*tan(alpha)**2*phid**2 - m*g)),
    Eq((m*z**2*tan(alpha)**2*phid).diff(t), 0),
]
