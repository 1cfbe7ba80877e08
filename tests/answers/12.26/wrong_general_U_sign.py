# expect: L=incorrect, eom=partial, coriolis=correct, centrifugal=correct
# +U(xp, yp) in L (U taken for a kinetic term), and the real force +dU/dxp in the first equation.
from sympy import Eq, Function, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
xp, yp = Function("xp")(t), Function("yp")(t)
U = Function("U")(xp, yp)
L = m / 2 * ((xp.diff(t) - omega * yp) ** 2 + (yp.diff(t) + omega * xp) ** 2) + U
eom = [
    Eq(m * xp.diff(t, 2), U.diff(xp) + 2 * m * omega * yp.diff(t) + m * omega**2 * xp),
    Eq(m * yp.diff(t, 2), -U.diff(yp) - 2 * m * omega * xp.diff(t) + m * omega**2 * yp),
]
coriolis = {"xp": 2 * m * omega * yp.diff(t), "yp": -2 * m * omega * xp.diff(t)}
centrifugal = {"xp": m * omega**2 * xp, "yp": m * omega**2 * yp}
