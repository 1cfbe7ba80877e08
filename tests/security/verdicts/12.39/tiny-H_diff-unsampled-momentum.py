# target: H_diff
# family: tiny
# expect: no-credit
# why: -omega*p_phip + k*exp(-100*(p_phip + 1)), huge for p_phip < -1: the negligible-part rule draws momenta from [-1.5, 1.5], the value comparison uses the true momenta (p_phip >= -0.8), where the term is below every tolerance
from sympy import symbols, exp
m, k, omega = symbols("m k omega", positive=True)
p_phip = symbols("p_phip")
H_diff = -omega*p_phip + k*exp(-100*(p_phip + 1))
