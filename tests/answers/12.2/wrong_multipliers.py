# expect: eom=incorrect
# The friction torque given the wrong sign: once lambda_1 is eliminated the cylinder is driven wrong.
from sympy import Eq, Function, symbols

t = symbols("t")
M, R, F = symbols("M R F", positive=True)
lambda_1 = symbols("lambda_1")
x, phi = Function("x")(t), Function("phi")(t)
eom = [Eq(M * x.diff(t, 2), F + lambda_1),
       Eq(M * R**2 / 2 * phi.diff(t, 2), R * lambda_1),
       Eq(x, R * phi)]
