# target: eom
# family: roots
# expect: no-credit
# why: the right equation times (m - 3): for a bob of mass 3 (above the sampled masses, which the wide test only scales down) it reads 0 = 0 and allows any theta''; the vanishing-factor test looks for a sign change only among the sampled states
from sympy import Eq, Function, sin, symbols
t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta = Function("theta")(t)
eom = [Eq((m - 3)*theta.diff(t, 2), -(m - 3)*g/l*sin(theta))]
