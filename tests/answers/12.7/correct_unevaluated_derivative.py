# expect: eom=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + r**2 * thd**2) + m * g * r * cos(theta) - k / 2 * (r - l0) ** 2
eom = [
    Eq(m * r.diff(t, 2), m * r * thd**2 + m * g * cos(theta) - k * (r - l0)),
    Eq(m * r**2 * theta.diff(t, 2) + 2 * m * r * rd * thd, -m * g * r * sin(theta)),
]
# (b) with theta = 0 the radial equation is m r'' = m g - k (r - l0): SHM about l0 + m g/k
omega = sqrt(k / m)

# ---- the form under test
# Lagrange's equations as d/dt(dL/dq') - dL/dq with the d/dt left unevaluated (issue 22).
from sympy import Derivative, Eq, Function, cos, sin, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
eom = [
    Eq(Derivative(m * r.diff(t), t), m * r * theta.diff(t) ** 2 + m * g * cos(theta) - k * (r - l0)),
    Eq(Derivative(m * r**2 * theta.diff(t), t), -m * g * r * sin(theta)),
]

from sympy import oo

pendulum = {k: oo}
oscillator = {theta: 0, theta.diff(t): 0}
