from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
I_c = Rational(2, 5)*M*R**2
omega_s = dot(s)/R
L = M*dot(s)**2/2 + I_c*omega_s**2/2 + M*g*s*sin(theta)
a = 5*g*sin(theta)/7
