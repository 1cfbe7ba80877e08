# expect: L_a=correct, eom_a=correct, L_b=correct, eom_b=correct, L_c=correct, eom_c=correct, L_d=incorrect, eom_d=incorrect
from lagrade.answer import *

m, g, k, l, h = parameters("m g k l h")
y = coordinates("y")
theta = coordinates("theta")
L_a = m*dot(y)**2/2 - m*g*y
eom_a = [Eq(dot(y, 2), -g)]
L_b = m*dot(y)**2/2 - k*y**2/2 + m*g*y
eom_b = [Eq(m*dot(y, 2), m*g - k*y)]
L_c = m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)
eom_c = [Eq(dot(theta, 2), -g/l*sin(theta))]
# used the rod's moment of inertia about its end instead of about O
L_d = m*l**2*dot(theta)**2/6 + m*g*h*cos(theta)
eom_d = [Eq(dot(theta, 2), -3*g*h*sin(theta)/l**2)]
