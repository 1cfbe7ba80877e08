# target: hamilton
# family: roots
# expect: no-credit
# why: theta' = p_theta/(m*l**2) times (p_theta - 10): at p_theta = 10 (beyond every momentum sampled or reached, |p_theta| < 6) it reads 0 = 0 and allows any theta'
from sympy import Eq, Function, sin, symbols
t = symbols("t")
m, l, g = symbols("m l g", positive=True)
theta, p_theta = Function("theta")(t), Function("p_theta")(t)
hamilton = [Eq((p_theta - 10)*theta.diff(t), (p_theta - 10)*p_theta/(m*l**2)),
            Eq(p_theta.diff(t), -m*g*l*sin(theta))]
