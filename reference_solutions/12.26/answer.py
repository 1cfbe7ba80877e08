"""Problem 12.26: particle in a plane, coordinates (xp, yp) along axes rotating with constant omega.

Inertial position R = xp e1' + yp e2' with de1'/dt = omega e2', de2'/dt = -omega e1', so the inertial
velocity has components (xp' - omega yp, yp' + omega xp) along the rotating axes. Real force: the book's
general potential U(xp, yp) (the problem's concrete one, U = k r^2/2, in tests/answers/12.26/correct_special_case_expanded.py).
L = m/2 [(xp' - omega yp)^2 + (yp' + omega xp)^2] - U(xp, yp)
Lagrange:  m xp'' = -dU/dxp + 2 m omega yp' + m omega^2 xp
           m yp'' = -dU/dyp - 2 m omega xp' + m omega^2 yp
i.e. m a' = F - 2 m omega x v' - m omega x (omega x r): Newton + Coriolis + centrifugal.
"""
from sympy import Eq, Function, symbols

t = symbols("t")
m, omega, k = symbols("m omega k")
xp, yp = Function("xp")(t), Function("yp")(t)
vx, vy = xp.diff(t), yp.diff(t)
U = Function("U")(xp, yp)

L = m / 2 * ((vx - omega * yp) ** 2 + (vy + omega * xp) ** 2) - U

eom = [
    Eq(m * xp.diff(t, 2), -U.diff(xp) + 2 * m * omega * vy + m * omega**2 * xp),
    Eq(m * yp.diff(t, 2), -U.diff(yp) - 2 * m * omega * vx + m * omega**2 * yp),
]
# -2 m omega x v' with omega = omega z: omega x v' = omega (-vy, vx)
coriolis = {"xp": 2 * m * omega * vy, "yp": -2 * m * omega * vx}
# -m omega x (omega x r) = m omega^2 r for r in the plane
centrifugal = {"xp": m * omega**2 * xp, "yp": m * omega**2 * yp}
