# expect: H=incorrect, cyclic=correct
from lagrade.answer import *

m, k = parameters("m k")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
H = (p_x**2 + p_y**2)/(2*m) - k/(x**2 + y**2)
hamilton = [Eq(dot(x), p_x/m), Eq(dot(y), p_y/m),
            Eq(p_x.diff(t), -2*k*x/(x**2 + y**2)**2), Eq(p_y.diff(t), -2*k*y/(x**2 + y**2)**2)]
cyclic = []
conserved = [m*(x*dot(y) - y*dot(x)), m*(dot(x)**2 + dot(y)**2)/2 - k/(x**2 + y**2)]
