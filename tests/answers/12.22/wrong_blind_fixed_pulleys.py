# expect: L=incorrect, a=incorrect, a_case=incorrect
from lagrade.answer import *

m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
# treated A and B as fixed: two independent Atwood machines
L = (m1 + m2)*dot(y)**2/2 + (m3 + m4)*dot(z)**2/2 + g*(m1 - m2)*y + g*(m3 - m4)*z
eom = [Eq(dot(x, 2), 0), Eq((m1 + m2)*dot(y, 2), (m1 - m2)*g), Eq((m3 + m4)*dot(z, 2), (m3 - m4)*g)]
a = {"m1": (m1 - m2)*g/(m1 + m2), "m2": (m2 - m1)*g/(m1 + m2),
     "m3": (m3 - m4)*g/(m3 + m4), "m4": (m4 - m3)*g/(m3 + m4)}
S_t = {"S1": 2*m1*m2*g/(m1 + m2), "S2": 2*m3*m4*g/(m3 + m4), "S3": 4*m1*m2*g/(m1 + m2)}
a_case = {k: v.subs({m1: m, m2: 2*m, m3: 3*m, m4: 4*m}) for k, v in a.items()}
