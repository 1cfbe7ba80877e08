# target: conserved
# family: tiny
# expect: no-credit
# why: the angular momentum plus k*exp(-300*p_y), which is not conserved (its rate is 300*k**2*y/r**3*exp(-300*p_y)), and huge for p_y < 0: the negligible-part rule draws momenta from [-1.5, 1.5], the comparison uses the true momenta (p_y > 0.3), where the term is below every tolerance
from sympy import *
t = symbols("t")
m, k = symbols("m k", positive=True)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = symbols("p_x p_y")
r = sqrt(x**2 + y**2)
conserved = [x*p_y - y*p_x + k*exp(-300*p_y), (p_x**2 + p_y**2)/(2*m) - k/r]
