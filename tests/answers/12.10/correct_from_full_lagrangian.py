# Derives the equation from the inertial-frame L (support at height a t^2/2) with sympy's euler_equations.
from sympy import Function, cos, pi, sin, sqrt, symbols
from sympy.calculus.euler import euler_equations

t = symbols("t")
m, l, g, a = symbols("m l g a", positive=True)
theta = Function("theta")(t)
x = l * sin(theta)
y = a * t**2 / 2 - l * cos(theta)
L = m / 2 * (x.diff(t) ** 2 + y.diff(t) ** 2) - m * g * y
eom = euler_equations(L, [theta], t)
period = 2 * pi * sqrt(l / (a + g))
