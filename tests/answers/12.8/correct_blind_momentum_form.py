from lagrade.answer import *

m, M, g, R = parameters("m M g R")
th = Symbol("theta")
x1, x2 = coordinates("x1 x2")
p = (m*cos(th)*dot(x2) + (M + m)*dot(x1))        # conserved horizontal momentum
L_a = p*dot(x1)/2 + m*dot(x2)**2/2 + m*cos(th)*dot(x1)*dot(x2)/2 + m*g*sin(th)*x2
eom_a = [Eq(p.diff(t), 0), Eq(m*dot(x2, 2) + m*cos(th)*dot(x1, 2) - m*g*sin(th), 0)]
X, theta = coordinates("X theta")
den = M + m*sin(theta)**2
L_b = M*dot(X)**2/2 + m*(dot(X)**2 + 2*R*cos(theta)*dot(X)*dot(theta) + R**2*dot(theta)**2)/2 - m*g*R*cos(theta)
eom_b = [Eq(dot(X, 2), m*sin(theta)*(R*dot(theta)**2 - g*cos(theta))/den),
         Eq(dot(theta, 2), (g*sin(theta)*(M + m) - m*R*sin(theta)*cos(theta)*dot(theta)**2)/(R*den))]
