"""Problem 12.44: quartic oscillator, V = k x^2/2 + eps x^4/4.

L = m x'^2/2 - k x^2/2 - eps x^4/4, p_x = m x', H = p_x^2/(2m) + k x^2/2 + eps x^4/4.
x' = dH/dp_x = p_x/m,  p_x' = -dH/dx = -k x - eps x^3.
"""
from sympy import Eq, Function, Rational, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
eps = symbols("eps", real=True)
x, p_x = Function("x")(t), Function("p_x")(t)

H = p_x**2 / (2 * m) + k * x**2 / 2 + Rational(1, 4) * eps * x**4
hamilton = [Eq(x.diff(t), p_x / m), Eq(p_x.diff(t), -k * x - eps * x**3)]
