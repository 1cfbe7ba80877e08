# expect: H=incorrect
from lagrade.answer import *

m, k, eps = parameters("m k eps")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2 + eps*x**4/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x - 2*eps*x**3)]
