from lagrade.answer import *

m, R, g = parameters("m R g")
theta0 = symbols("theta0")
rho, theta = coordinates("rho theta")
w = sqrt(g/R)
# energy from the top: theta'^2 = 4 (g/R) sin^2(theta/2)  =>  tan(theta/4) grows like exp(w t)
solution = {theta: 4*atan(tan(theta0/4)*exp(w*t))}
N = m*g*(3*cos(theta) - 2)
leave_angle = acos(Rational(2, 3))
