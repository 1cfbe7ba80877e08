# expect: H=correct, hamilton=correct, solution=incorrect, omega=correct
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x)]
omega = sqrt(k/m)
solution = {x: x0 + v0*t - omega**2*x0*t**2/2 - omega**2*v0*t**3/6}   # right initial values, not the motion
