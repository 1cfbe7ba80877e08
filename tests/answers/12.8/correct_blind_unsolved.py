from lagrade.answer import *

m, M, g, R = parameters("m M g R")
theta_a = Symbol("theta")            # system (a): the face's angle is a parameter
x1, x2 = coordinates("x1 x2")
vx = dot(x1) + dot(x2)*cos(theta_a)
vy = -dot(x2)*sin(theta_a)
L_a = M*dot(x1)**2/2 + m*(vx**2 + vy**2)/2 + m*g*x2*sin(theta_a)
eom_a = [Eq((M + m)*dot(x1, 2) + m*cos(theta_a)*dot(x2, 2), 0),
         Eq(dot(x2, 2) + cos(theta_a)*dot(x1, 2), g*sin(theta_a))]
X, theta = coordinates("X theta")
L_b = (M + m)*dot(X)**2/2 + m*R*cos(theta)*dot(X)*dot(theta) + m*R**2*dot(theta)**2/2 - m*g*R*cos(theta)
eom_b = [(M + m)*dot(X, 2) + m*R*(cos(theta)*dot(theta, 2) - sin(theta)*dot(theta)**2),
         cos(theta)*dot(X, 2) + R*dot(theta, 2) - g*sin(theta)]
