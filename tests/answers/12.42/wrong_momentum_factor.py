# expect: H=incorrect, hamilton=partial, solution=correct, omega=correct
# x' = p*m instead of p/m (T = m*p**2/2).
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x, p_x = coordinates("x p_x")
H = m * p_x**2 / 2 + k * x**2 / 2
hamilton = [Eq(dot(x), m * p_x), Eq(dot(p_x), -k * x)]
w = sqrt(k / m)
solution = {x: x0 * cos(w * t) + v0 / w * sin(w * t)}
omega = w
