"""Problem 12.13: rod (M, l) pivoted at O with a disk (M, R) on a frictionless pin at its lower end.

T = (1/2)(M l^2/3) theta'^2 + (1/2) M (l theta')^2 + (1/2)(M R^2/2) psi'^2 = 2 M l^2 theta'^2/3 + M R^2 psi'^2/4
V = -M g (l/2) cos(theta) - M g l cos(theta) = -3 M g l cos(theta)/2
theta: (4/3) M l^2 theta'' = -(3/2) M g l sin(theta) -> theta'' = -9 g sin(theta)/(8 l)
psi: cyclic -> psi' = const: the disk keeps its orientation-rate while its centre swings.
Small swings: omega^2 = 9 g/(8 l), period 2 pi sqrt(8 l/(9 g)).
"""
from sympy import Eq, Function, Rational, cos, pi, sin, sqrt, symbols

t = symbols("t")
M, l, R, g = symbols("M l R g", positive=True)
theta, psi = Function("theta")(t), Function("psi")(t)

L = Rational(2, 3) * M * l**2 * theta.diff(t) ** 2 + M * R**2 * psi.diff(t) ** 2 / 4 + Rational(3, 2) * M * g * l * cos(theta)
eom = [Eq(theta.diff(t, 2), -9 * g * sin(theta) / (8 * l)), Eq(psi.diff(t, 2), 0)]
cyclic = ["psi"]
conserved = [M * R**2 * psi.diff(t) / 2]   # p_psi
period = 2 * pi * sqrt(8 * l / (9 * g))
