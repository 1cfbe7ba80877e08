# expect: H=correct, hamilton=correct, solution=incorrect, omega=incorrect
# Sine term without the 1/omega (x'(0) comes out v0*omega); omega inverted.
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) + k * x**2 / 2
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), -k * x)]
w = sqrt(k / m)
solution = {x: x0 * cos(w * t) + v0 * sin(w * t)}
omega = sqrt(m / k)
