# expect: H=correct, hamilton=correct, cyclic=incorrect, conserved=correct
from lagrade.answer import *

m, k = parameters("m k")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
r = sqrt(x**2 + y**2)
H = (p_x**2 + p_y**2)/(2*m) - k/r
hamilton = [Eq(dot(x), p_x/m), Eq(dot(y), p_y/m),
            Eq(p_x.diff(t), -k*x/r**3), Eq(p_y.diff(t), -k*y/r**3)]
cyclic = ["x", "y"]
conserved = [m*(x*dot(y) - y*dot(x)), m*(dot(x)**2 + dot(y)**2)/2 - k/r]
