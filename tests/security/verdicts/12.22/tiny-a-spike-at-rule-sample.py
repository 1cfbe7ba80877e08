# target: a
# family: tiny
# expect: no-credit
# why: a_m1 plus g*exp(-10**10*(m1 - 1472/949)**2): a spike of size g at m1 = 1472/949, within 1.3e-6 of one of the rule's own 24 fixed (crc32-seeded) states, where it is not negligible, and zero where the comparison samples
from sympy import *
m1, m2, m3, m4, g = symbols("m1 m2 m3 m4 g", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
a = {"m1": g - S/m1 + g*exp(-10**10*(m1 - Rational(1472, 949))**2), "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
