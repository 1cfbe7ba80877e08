# expect: H=incorrect, hamilton=partial, solution=incorrect, omega=correct
# H written as T - V (the Lagrangian in the momenta); the "solution" then grows like cosh.
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) - k * x**2 / 2
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), k * x)]
w = sqrt(k / m)
solution = {x: x0 * cosh(w * t) + v0 / w * sinh(w * t)}
omega = sqrt(k / m)
