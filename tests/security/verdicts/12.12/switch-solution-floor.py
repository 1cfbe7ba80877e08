# target: solution
# family: switch
# expect: no-credit
# why: r(t) is multiplied by 1 - floor(t/3): zero from t = 3 on
from sympy import *

t = symbols("t")
m, g, omega, r0, v0 = symbols("m g omega r0 v0", positive=True)
r = Function("r")(t)
right = (r0*cosh(omega*t) + (v0/omega - g/(2*omega**2))*sinh(omega*t)
         + g*sin(omega*t)/(2*omega**2))

solution = {"r": (1 - floor(t/3))*right}
