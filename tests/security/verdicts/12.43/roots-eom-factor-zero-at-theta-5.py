# target: eom
# family: roots
# expect: no-credit
# why: the right equation times (theta - 5): at theta = 5 rad (beyond the sampled [-2.5, 2.5], an angle a pendulum that goes over the top reaches) it reads 0 = 0 and allows any theta''
from sympy import Eq, Function, sin, symbols
t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta = Function("theta")(t)
eom = [Eq((theta - 5)*theta.diff(t, 2), -(theta - 5)*g/l*sin(theta))]
