# target: eom
# family: honest
# expect: full-marks
# why: nothing: dry friction written with sign(theta') and drag with theta'*sqrt(theta'**2): the ring slides with theta' > 0
from sympy import *

t = symbols("t")
m, a, c, mu, v0 = symbols("m a c mu v0", positive=True)
theta = Function("theta")(t)
thd = theta.diff(t)
eom = [Eq(theta.diff(t, 2), -mu*thd**2*sign(thd) - c*a/m*thd*sqrt(thd**2))]
