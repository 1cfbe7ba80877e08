# The book's general potential U(xp, yp): L with U, the real force as Derivative(U(xp, yp), xp) and as
# the Subs form sympy gives for a partial derivative at a point; the equations in Newton's form, solved.
from sympy import Derivative, Eq, Function, Subs, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
xp, yp = Function("xp")(t), Function("yp")(t)
U = Function("U")
a, b = symbols("a b")
L = m * (xp.diff(t)**2 + yp.diff(t)**2) / 2 + m * omega * (xp * yp.diff(t) - yp * xp.diff(t)) \
    + m * omega**2 * (xp**2 + yp**2) / 2 - U(xp, yp)
eom = [
    Eq(xp.diff(t, 2), (-Derivative(U(xp, yp), xp) + 2 * m * omega * yp.diff(t) + m * omega**2 * xp) / m),
    Eq(yp.diff(t, 2), (-Subs(Derivative(U(a, b), b), (a, b), (xp, yp)) - 2 * m * omega * xp.diff(t)
                       + m * omega**2 * yp) / m),
]
coriolis = {"xp": 2 * m * omega * yp.diff(t), "yp": -2 * m * omega * xp.diff(t)}
centrifugal = {"xp": m * omega**2 * xp, "yp": m * omega**2 * yp}
