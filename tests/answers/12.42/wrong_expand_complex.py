# expect: solution=incorrect
# The same, with the velocity term's sign wrong: re(t), im(t) are read, and the answer is simply wrong.
from sympy import I, exp, expand, sqrt, symbols

t = symbols("t")
m, k = symbols("m k", positive=True)
x0, v0 = symbols("x0 v0")
w = sqrt(k / m)
A = (x0 + I * v0 / w) / 2
solution = {"x": expand(A * exp(I * w * t) + A.conjugate() * exp(-I * w * t), complex=True)}
