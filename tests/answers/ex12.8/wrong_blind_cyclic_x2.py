# expect: H=correct, hamilton=correct, cyclic=incorrect, conserved=incorrect
from lagrade.answer import *

m, M, g, theta = parameters("m M g theta")
x1, x2 = coordinates("x1 x2")
p_x1, p_x2 = momenta("p_x1 p_x2")
c, s = cos(theta), sin(theta)
D = m*(M + m*s**2)
H = (m*p_x1**2 - 2*m*c*p_x1*p_x2 + (M + m)*p_x2**2)/(2*D) - m*g*x2*s
hamilton = [Eq(dot(x1), (m*p_x1 - m*c*p_x2)/D), Eq(dot(x2), ((M + m)*p_x2 - m*c*p_x1)/D),
            Eq(p_x1.diff(t), 0), Eq(p_x2.diff(t), m*g*s)]
cyclic = ["x2"]
conserved = [m*dot(x2) + m*c*dot(x1)]
