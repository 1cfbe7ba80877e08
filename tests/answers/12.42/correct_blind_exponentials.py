from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = symbols("p_x")
P = momenta("p_x")
H = (p_x**2 + m*k*x**2)/(2*m)
hamilton = [Eq(m*dot(x), P), Eq(P.diff(t) + k*x, 0)]
w = sqrt(k/m)
c = (x0 - I*v0/w)/2
solution = {"x": c*exp(I*w*t) + conjugate(c)*exp(-I*w*t)}
omega = w
