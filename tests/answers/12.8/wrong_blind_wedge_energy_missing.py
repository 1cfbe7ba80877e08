# expect: L_a=incorrect, L_b=correct, eom_b=correct
from lagrade.answer import *

m, M, g, R = parameters("m M g R")
th = Symbol("theta")
x1, x2 = coordinates("x1 x2")
L_a = m*((dot(x1) + dot(x2)*cos(th))**2 + (dot(x2)*sin(th))**2)/2 + m*g*x2*sin(th)
eom_a = [Eq(dot(x1, 2) + cos(th)*dot(x2, 2), 0), Eq(dot(x2, 2) + cos(th)*dot(x1, 2), g*sin(th))]
X, theta = coordinates("X theta")
L_b = M*dot(X)**2/2 + m*((dot(X) + R*cos(theta)*dot(theta))**2 + (R*sin(theta)*dot(theta))**2)/2 - m*g*R*cos(theta)
eom_b = [(M + m)*dot(X, 2) + m*R*cos(theta)*dot(theta, 2) - m*R*sin(theta)*dot(theta)**2,
         cos(theta)*dot(X, 2) + R*dot(theta, 2) - g*sin(theta)]
