from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
depths = {m1: x + y, m2: x + l1 - y, m3: l3 - x + z, m4: l3 - x + l2 - z}
L = sum(mi*d.diff(t)**2/2 + mi*g*d for mi, d in depths.items())
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (x, y, z)]
D = m1*m2*(m3 + m4) + m3*m4*(m1 + m2)
xdd = g*(m1*m2*(m3 + m4) - m3*m4*(m1 + m2))/D
ydd = 2*g*m3*m4*(m1 - m2)/D
zdd = 2*g*m1*m2*(m3 - m4)/D
a = {"m1": xdd + ydd, "m2": xdd - ydd, "m3": -xdd + zdd, "m4": -xdd - zdd}
S1 = 4*g*m1*m2*m3*m4/D
S_t = {"S1": S1, "S2": S1, "S3": 2*S1}
a_case = {k: simplify(v.subs({m1: m, m2: 2*m, m3: 3*m, m4: 4*m})) for k, v in a.items()}
