"""Problem 12.25: uniform solid sphere rolling without slipping down a fixed incline of angle theta.

s = distance of the centre down the slope; rolling: omega = s'/R, I = 2 M R^2/5.
T = M s'^2/2 + I omega^2/2 = (7/10) M s'^2, V = -M g s sin(theta).
Lagrange: (7/5) M s'' = M g sin(theta)  ->  s'' = 5 g sin(theta)/7.
"""
from sympy import Rational, Function, sin, symbols

t = symbols("t")
M, R, g, theta = symbols("M R g theta", positive=True)
s = Function("s")(t)
sd = s.diff(t)

I = Rational(2, 5) * M * R**2
T = M * sd**2 / 2 + I * (sd / R) ** 2 / 2
V = -M * g * s * sin(theta)
L = T - V

a = Rational(5, 7) * g * sin(theta)
