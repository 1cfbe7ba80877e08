"""Problem 12.10: in the frame of the support, gravity is effectively g + a."""
from sympy import Eq, Function, pi, sin, sqrt, symbols

t = symbols("t")
m, l, g, a = symbols("m l g a", positive=True)
theta = Function("theta")(t)

eom = [Eq(l * theta.diff(t, 2), -(g + a) * sin(theta))]
period = 2 * pi * sqrt(l / (g + a))
