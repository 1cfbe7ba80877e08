# target: hamilton
# family: tiny
# expect: no-credit
# why: y' = p_y/m - 100*k*exp(-100*p_y), wrong (hugely) for p_y < 0: the negligible-part rule draws momenta from [-1.5, 1.5], the comparison uses the true momenta (p_y >= 0.44 at its states), where the term is below 1e-17 of the rate
from sympy import Eq, Function, sqrt, symbols, exp
t = symbols("t")
m, k = symbols("m k", positive=True)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
r = sqrt(x**2 + y**2)
hamilton = [Eq(x.diff(t), p_x/m), Eq(y.diff(t), p_y/m - 100*k*exp(-100*p_y)),
            Eq(p_x.diff(t), -k*x/r**3), Eq(p_y.diff(t), -k*y/r**3)]
