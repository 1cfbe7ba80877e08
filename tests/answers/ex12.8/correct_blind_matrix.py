from lagrade.answer import *

m, M, g, theta = parameters("m M g theta")
x1, x2 = coordinates("x1 x2")
p1, p2 = symbols("p_x1 p_x2")
P1, P2 = momenta("p_x1 p_x2")
Mm = Matrix([[M + m, m*cos(theta)], [m*cos(theta), m]])
p = Matrix([p1, p2])
H = simplify((p.T*Mm.inv()*p)[0]/2) - m*g*x2*sin(theta)
qdot = Mm.inv()*Matrix([P1, P2])
hamilton = [Eq(dot(x1), qdot[0]), Eq(dot(x2), qdot[1]), P1.diff(t), Eq(P2.diff(t), m*g*sin(theta))]
cyclic = [x1]
conserved = [(Mm*Matrix([dot(x1), dot(x2)]))[0]]
