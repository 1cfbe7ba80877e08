# The leave angle given as a number via asin(sqrt(5)/3) (sin of acos(2/3)).
from sympy import Function, Symbol, asin, atan, cos, exp, sqrt, symbols, tan

t = Symbol("t")
m, R, g, theta0 = symbols("m R g theta0")
theta = Function("theta")(t)
N = 3 * m * g * cos(theta) - 2 * m * g
leave_angle = asin(sqrt(5) / 3)
solution = {theta: 4 * atan(tan(theta0 / 4) * exp(sqrt(g / R) * t))}
