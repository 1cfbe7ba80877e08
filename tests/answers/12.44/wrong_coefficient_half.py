# expect: H=incorrect, hamilton=partial
# Ignores the published reading V = k*x**2/2 + eps*x**4/4 and uses eps*x**4/2: the force comes out -k*x - 2*eps*x**3.
from lagrade.answer import *

m, k, eps = parameters("m k eps")
x, p_x = coordinates("x p_x")
H = p_x**2 / (2 * m) + k * x**2 / 2 + eps * x**4 / 2
hamilton = [Eq(dot(x), p_x / m), Eq(dot(p_x), -k * x - 2 * eps * x**3)]
