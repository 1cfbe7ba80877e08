"""Problem 12.4: particle on the outside of a hoop, released from rest at the top.

Energy from the top: R theta'^2 = 2 g (1 - cos theta). Radial equation with the normal force N:
m R theta'^2 = m g cos(theta) - N  ->  N = m g (3 cos(theta) - 2), zero at cos(theta) = 2/3.
Separatrix: theta' = 2 sqrt(g/R) sin(theta/2) integrates to tan(theta/4) = tan(theta0/4) exp(sqrt(g/R) t).
"""
from sympy import Function, Rational, acos, atan, cos, exp, sqrt, symbols, tan

t = symbols("t")
m, R, g, theta0 = symbols("m R g theta0", positive=True)
theta = symbols("theta")

solution = {"theta": 4 * atan(tan(theta0 / 4) * exp(sqrt(g / R) * t))}
N = m * g * (3 * cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
