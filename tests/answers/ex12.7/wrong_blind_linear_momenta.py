# expect: H=correct, hamilton=correct, cyclic=correct, conserved=incorrect
from lagrade.answer import *

m, k = parameters("m k")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
H = (p_x**2 + p_y**2)/(2*m) - k/sqrt(x**2 + y**2)
hamilton = [Eq(dot(x), p_x/m), Eq(dot(y), p_y/m),
            Eq(p_x.diff(t), -k*x/(x**2 + y**2)**Rational(3, 2)), Eq(p_y.diff(t), -k*y/(x**2 + y**2)**Rational(3, 2))]
cyclic = []
conserved = [m*dot(x), m*dot(y)]
