# target: eom
# family: honest
# expect: full-marks
# why: nothing: the z equation multiplied through by cos(alpha)**2, a factor that is not zero for 0 < alpha < pi/2
from sympy import *

t = symbols("t")
m, g, h, alpha = symbols("m g h alpha", positive=True)
z, phi = Function("z")(t), Function("phi")(t)
zd, phid = z.diff(t), phi.diff(t)
eom = [
    Eq(m*z.diff(t, 2), cos(alpha)**2*(m*z*tan(alpha)**2*phid**2 - m*g)),
    Eq((m*z**2*tan(alpha)**2*phid).diff(t), 0),
]
