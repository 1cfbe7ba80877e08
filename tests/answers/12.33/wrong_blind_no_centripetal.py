# expect: L=correct, eom=correct, N=incorrect, leave_angle=incorrect
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
b = R + r_s
L = m*b**2*dot(theta)**2/2 - m*g*b*cos(theta)
eom = [Eq(b*dot(theta, 2), g*sin(theta))]
lam = m*g*cos(theta) - m*b*dot(theta)**2
N = m*g*cos(theta)                  # forgot the centripetal term
leave_angle = pi/2
