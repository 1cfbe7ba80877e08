# expect: H=correct, hamilton=correct, solution=incorrect, omega=correct
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x)]
omega = sqrt(k/m)
# A*sin(omega*t + phi) with phi = atan(omega*x0/v0): right only when v0 > 0
solution = {x: sqrt(x0**2 + v0**2/omega**2)*sin(omega*t + atan(omega*x0/v0))}
