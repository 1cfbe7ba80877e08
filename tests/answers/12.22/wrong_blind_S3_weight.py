# expect: L=correct, eom=correct, a=correct, a_case=correct
from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
L = (m1*(dot(x) + dot(y))**2 + m2*(dot(x) - dot(y))**2 + m3*(dot(z) - dot(x))**2 + m4*(dot(x) + dot(z))**2)/2 \
    + g*(m1*(x + y) + m2*(x - y) + m3*(z - x) - m4*(x + z))
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (x, y, z)]
D = m1*m2*(m3 + m4) + m3*m4*(m1 + m2)
a = {"m1": g - 4*g*m2*m3*m4/D, "m2": g - 4*g*m1*m3*m4/D, "m3": g - 4*g*m1*m2*m4/D, "m4": g - 4*g*m1*m2*m3/D}
S_t = {"S1": 4*g*m1*m2*m3*m4/D, "S2": 4*g*m1*m2*m3*m4/D, "S3": (m1 + m2 + m3 + m4)*g}
a_case = {"m1": -Rational(23, 25)*g, "m2": g/25, "m3": Rational(9, 25)*g, "m4": Rational(13, 25)*g}
