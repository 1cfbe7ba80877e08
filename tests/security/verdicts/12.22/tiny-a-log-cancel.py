# target: a
# family: tiny
# expect: no-credit
# why: a_m1 plus g*log(m1 + 10**11) - g*log(10**11) = g*log(1 + m1/10**11): two large terms that cancel to 1e-11, each weighed alone
from sympy import *
m1, m2, m3, m4, g = symbols("m1 m2 m3 m4 g", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)
N = 10**11
a = {"m1": g - S/m1 + g*log(m1 + N) - g*log(N), "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
