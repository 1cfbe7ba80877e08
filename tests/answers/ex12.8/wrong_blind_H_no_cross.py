# expect: H=incorrect, cyclic=correct, conserved=correct
from lagrade.answer import *

m, M, g, theta = parameters("m M g theta")
x1, x2 = coordinates("x1 x2")
p_x1, p_x2 = momenta("p_x1 p_x2")
H = p_x1**2/(2*(M + m)) + p_x2**2/(2*m) - m*g*x2*sin(theta)
hamilton = [Eq(dot(x1), p_x1/(M + m)), Eq(dot(x2), p_x2/m), Eq(p_x1.diff(t), 0), Eq(p_x2.diff(t), m*g*sin(theta))]
cyclic = ["x1"]
conserved = [(M + m)*dot(x1) + m*cos(theta)*dot(x2)]
