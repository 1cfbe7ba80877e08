from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
L = (m1*(dot(x) + dot(y))**2 + m2*(dot(x) - dot(y))**2 + m3*(dot(z) - dot(x))**2 + m4*(dot(x) + dot(z))**2)/2 \
    + g*(m1*(x + y) + m2*(x + l1 - y) + m3*(l3 - x + z) + m4*(l3 - x + l2 - z))
D = m1*m2*(m3 + m4) + m3*m4*(m1 + m2)
eom = [Eq(dot(x, 2), g*(m1*m2*(m3 + m4) - m3*m4*(m1 + m2))/D),
       Eq(dot(y, 2), 2*g*m3*m4*(m1 - m2)/D),
       Eq(dot(z, 2), 2*g*m1*m2*(m3 - m4)/D)]
a = {"m1": g - 4*g*m2*m3*m4/D, "m2": g - 4*g*m1*m3*m4/D, "m3": g - 4*g*m1*m2*m4/D, "m4": g - 4*g*m1*m2*m3/D}
S_t = {"S1": 4*g*m1*m2*m3*m4/D, "S2": 4*g*m1*m2*m3*m4/D, "S3": 8*g*m1*m2*m3*m4/D}
a_case = {"m1": -0.92*g, "m2": 0.04*g, "m3": 0.36*g, "m4": 0.52*g}
