# The example's two-coordinate Lagrangian with the constraint y = R*theta substituted (a: y -> R*theta,
# b: theta -> y/R), plus a total time derivative in (b); the solution written with factored time dependence.
from sympy import Eq, Function, Rational, sin, symbols

t = symbols("t")
M, R, g, l, phi = symbols("M R g l phi")
theta0, w0, y0, v0 = symbols("theta0 w0 y0 v0")
theta, y = Function("theta")(t), Function("y")(t)


def L_two(yd, thd, yy):
    return M / 2 * yd**2 + M * R**2 / 4 * thd**2 - M * g * (l - yy) * sin(phi)


L_a = L_two(R * theta.diff(t), theta.diff(t), R * theta)
L_b = L_two(y.diff(t), y.diff(t) / R, y) + (M * g * y**2).diff(t)
eom_a = [Eq(theta.diff(t, 2), 2 * g * sin(phi) / (3 * R))]
eom_b = [Eq(3 * y.diff(t, 2), 2 * g * sin(phi))]
solution_a = {theta: theta0 + t * (w0 + t * g * sin(phi) / (3 * R))}
solution_b = {y: y0 + t * (v0 + g * sin(phi) * t / 3)}
a = Rational(2, 3) * g * sin(phi)
