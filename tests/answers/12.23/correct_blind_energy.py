from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = symbols("theta0")
theta = coordinates("theta")
I_cm = M*l**2/12
v_cm2 = (l/2)**2*dot(theta)**2
L = M*v_cm2/2 + I_cm*dot(theta)**2/2 - M*g*l*sin(theta)/2
eom = [Eq(dot(theta, 2), -3*g*cos(theta)/(2*l))]
N_w = 3*M*g*sin(theta)*cos(theta)/4 - M*l*cos(theta)*dot(theta)**2/2
leave_angle = asin(2*sin(theta0)/3)
