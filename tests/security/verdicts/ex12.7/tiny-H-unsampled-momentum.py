# target: H
# family: tiny
# expect: no-credit
# why: H + k*exp(-300*p_y), huge for p_y < 0: the negligible-part rule draws momenta from [-1.5, 1.5], the comparison uses the true momenta (p_y >= 0.34 at its states, the motions start at p_y >= 0.88), where the term is below 1e-40 of H
from sympy import Function, sqrt, symbols, exp
t = symbols("t")
m, k = symbols("m k", positive=True)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
H = (p_x**2 + p_y**2)/(2*m) - k/sqrt(x**2 + y**2) + k*exp(-300*p_y)
