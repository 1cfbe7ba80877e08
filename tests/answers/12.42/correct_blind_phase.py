from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x)]
omega = sqrt(k/m)
A = sqrt(x0**2 + v0**2/omega**2)
delta = atan2(v0/omega, x0)
solution = {x: A*cos(omega*t - delta)}
