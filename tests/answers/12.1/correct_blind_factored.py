from lagrade.answer import *

m, g, k, l, h = parameters("m g k l h")
y = coordinates("y")
theta = coordinates("theta")

L_a = m*(dot(y)**2/2 - g*y)
eom_a = [Eq(dot(y, 2), -g)]
L_b = -(k*y**2 - 2*m*g*y - m*dot(y)**2)/2
eom_b = [m*dot(y, 2) + k*y - m*g]
L_c = m*l**2*dot(theta)**2/2 - m*g*l*(1 - cos(theta))
eom_c = [Eq(l*dot(theta, 2) + g*sin(theta), 0)]
I_O = m*l**2/12 + m*h**2          # parallel axes
L_d = I_O*dot(theta)**2/2 + m*g*h*cos(theta)
eom_d = [Eq(dot(theta, 2), -12*g*h*sin(theta)/(l**2 + 12*h**2))]
