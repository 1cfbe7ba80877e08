# target: hamilton
# family: complex
# expect: no-credit
# why: each equation has an imaginary term 1000*I*k
from sympy import *

t = symbols("t")
m, k = symbols("m k", positive=True)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
r = sqrt(x**2 + y**2)
hamilton = [Eq(x.diff(t), p_x/m + 1000*I*k), Eq(y.diff(t), p_y/m + 1000*I*k),
            Eq(p_x.diff(t), -k*x/r**3 + 1000*I*k), Eq(p_y.diff(t), -k*y/r**3 + 1000*I*k)]
