# expect: eom=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cos, sin, symbols

t = symbols("t")
m, M, r_h, g, phi, s0 = symbols("m M r_h g phi s0", positive=True)
X, s = Function("X")(t), Function("s")(t)
Xd, sd = X.diff(t), s.diff(t)

L = (M + m) / 2 * Xd**2 + m * cos(phi) * Xd * sd + m * sd**2 + m * g * s * sin(phi)
eom = [
    Eq((M + m) * X.diff(t, 2) + m * cos(phi) * s.diff(t, 2), 0),
    Eq(2 * s.diff(t, 2) + cos(phi) * X.diff(t, 2), g * sin(phi)),
]
D = 2 * M + m + m * sin(phi) ** 2
a_s = (M + m) * g * sin(phi) / D
a_X = -m * g * sin(phi) * cos(phi) / D
solution = {"X": a_X * t**2 / 2, "s": s0 + a_s * t**2 / 2}

# ---- the form under test
# Both accelerations solved for at once: {X'': ..., s'': ...} (issue 22).
from sympy import Eq, Function, cos, sin, solve, symbols

t = symbols("t")
m, M, r_h, g, phi = symbols("m M r_h g phi", positive=True)
X, s = Function("X")(t), Function("s")(t)
eom = solve([Eq((M + m) * X.diff(t, 2) + m * cos(phi) * s.diff(t, 2), 0),
             Eq(2 * s.diff(t, 2) + cos(phi) * X.diff(t, 2), g * sin(phi))], [X.diff(t, 2), s.diff(t, 2)])
