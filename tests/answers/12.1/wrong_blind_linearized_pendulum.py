# expect: L_a=correct, eom_a=correct, L_b=correct, eom_b=correct, L_c=correct, eom_c=incorrect, L_d=correct, eom_d=correct
from lagrade.answer import *

m, g, k, l, h = parameters("m g k l h")
y = coordinates("y")
theta = coordinates("theta")
L_a = m*dot(y)**2/2 - m*g*y
eom_a = [dot(y, 2) + g]
L_b = m*dot(y)**2/2 - k*y**2/2 + m*g*y
eom_b = [m*dot(y, 2) - m*g + k*y]
L_c = m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)
eom_c = [Eq(dot(theta, 2), -g/l*theta)]      # small-angle form, but the exact equation was asked
L_d = (m*l**2/12 + m*h**2)*dot(theta)**2/2 + m*g*h*cos(theta)
eom_d = [Eq((m*l**2/12 + m*h**2)*dot(theta, 2), -m*g*h*sin(theta))]
