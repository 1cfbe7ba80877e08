# target: a
# family: honest
# expect: full-marks
# why: nothing: exp(m1 + m2) = exp(m1)*exp(m2), and cosh(I*u) = cos(u)
from sympy import *

t = symbols("t")
m1, m2, m3, m4, g, l1, l2, l3, m = symbols("m1 m2 m3 m4 g l1 l2 l3 m", positive=True)
S = 4*g/(1/m1 + 1/m2 + 1/m3 + 1/m4)

a = {"m1": g*exp(m1 + m2)*exp(-m1)*exp(-m2)*(cosh(I*m1)**2 + sin(m1)**2) - S/m1, "m2": g - S/m2, "m3": g - S/m3, "m4": g - S/m4}
