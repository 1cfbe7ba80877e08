# target: solution
# family: floats
# expect: no-credit
# why: r(t) is 1.000000001 times the true motion: it does not meet r(0) = r0
from sympy import *

t = symbols("t")
m, g, omega, r0, v0 = symbols("m g omega r0 v0", positive=True)
r = Function("r")(t)
right = (r0*cosh(omega*t) + (v0/omega - g/(2*omega**2))*sinh(omega*t)
         + g*sin(omega*t)/(2*omega**2))

solution = {"r": Float("1.000000001")*right}
