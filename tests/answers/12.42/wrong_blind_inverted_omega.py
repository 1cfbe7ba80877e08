# expect: H=correct, hamilton=correct, solution=incorrect, omega=incorrect
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x)]
omega = sqrt(m/k)
solution = {x: x0*cos(omega*t) + v0/omega*sin(omega*t)}
