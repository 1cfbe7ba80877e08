# expect: solution=incorrect, N=correct, leave_angle=correct
from lagrade.answer import *

m, R, g = parameters("m R g")
theta0 = symbols("theta0")
rho, theta = coordinates("rho theta")
w = sqrt(g/R)
solution = {theta: 2*atan(tan(theta0/2)*exp(w*t))}        # integrated d(theta)/sin(theta) instead of sin(theta/2)
N = m*g*(3*cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
