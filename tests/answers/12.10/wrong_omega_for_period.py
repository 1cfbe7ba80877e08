# expect: period=incorrect, eom=correct
# Gives the angular frequency sqrt((g + a)/l) where the period is asked.
from sympy import Eq, Function, sin, sqrt, symbols

t = symbols("t")
m, l, g, a = symbols("m l g a")
theta = Function("theta")(t)
eom = [Eq(l * theta.diff(t, 2), -(g + a) * sin(theta))]
period = sqrt((g + a) / l)
