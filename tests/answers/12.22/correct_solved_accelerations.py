# eom solved for x'', y'', z'' with the common denominator written per equation; S3 = S1 + S2; a from the coordinates.
from sympy import Eq, Function, Rational, symbols

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = Function("x")(t), Function("y")(t), Function("z")(t)
L = m1 / 2 * (x.diff(t) + y.diff(t)) ** 2 + m2 / 2 * (x.diff(t) - y.diff(t)) ** 2 \
    + m3 / 2 * (z.diff(t) - x.diff(t)) ** 2 + m4 / 2 * (x.diff(t) + z.diff(t)) ** 2 \
    + g * (m1 * x + m1 * y + m2 * x - m2 * y - m3 * x + m3 * z - m4 * x - m4 * z) + 5 * g * m1 * l1
D = m1 * m2 * (m3 + m4) + m3 * m4 * (m1 + m2)
xdd = g * (m1 * m2 * (m3 + m4) - m3 * m4 * (m1 + m2)) / D
ydd = 2 * g * m3 * m4 * (m1 - m2) / D
zdd = 2 * g * m1 * m2 * (m3 - m4) / D
eom = [Eq(D * x.diff(t, 2), D * xdd), Eq(D * z.diff(t, 2) / (2 * m1 * m2), g * (m3 - m4)), Eq(y.diff(t, 2), ydd)]
a = {"m1": xdd + ydd, "m2": xdd - ydd, "m3": zdd - xdd, "m4": -xdd - zdd}
S1 = m1 * (g - xdd - ydd)
S2 = m3 * (g + xdd - zdd)
S_t = {"S1": S1, "S2": S2, "S3": S1 + S2}
a_case = {"m1": Rational(-23, 25) * g, "m2": Rational(1, 25) * g, "m3": Rational(9, 25) * g, "m4": Rational(13, 25) * g}
