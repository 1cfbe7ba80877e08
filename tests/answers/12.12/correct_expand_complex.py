# expect: solution=correct
# The other parts as in the reference solution; the form under test is bound last.
from sympy import Eq, Function, cosh, sin, sinh, symbols

t = symbols("t")
m, g, omega, r0, v0 = symbols("m g omega r0 v0", positive=True)
r = Function("r")(t)

L = m * (r.diff(t) ** 2 + omega**2 * r**2) / 2 - m * g * r * sin(omega * t)
eom = [Eq(r.diff(t, 2), omega**2 * r - g * sin(omega * t))]
solution = {"r": r0 * cosh(omega * t) + (v0 / omega - g / (2 * omega**2)) * sinh(omega * t)
            + g * sin(omega * t) / (2 * omega**2)}
H_conserved = False

# ---- the form under test
# The particular solution written with complex exponentials and expanded with expand(complex=True),
# which leaves re(t) and im(t) (t is not declared real) (issue 22).
from sympy import I, Function, cosh, exp, expand, sinh, symbols

t = symbols("t")
m, g, omega, r0, v0 = symbols("m g omega r0 v0", positive=True)
r = Function("r")(t)
sin_wt = (exp(I * omega * t) - exp(-I * omega * t)) / (2 * I)
solution = {"r": expand(r0 * cosh(omega * t) + (v0 / omega - g / (2 * omega**2)) * sinh(omega * t)
                        + g * sin_wt / (2 * omega**2), complex=True)}
