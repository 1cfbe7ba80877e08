# expect: solution=incorrect, N=correct, leave_angle=correct
from lagrade.answer import *

m, R, g = parameters("m R g")
theta0 = symbols("theta0")
rho, theta = coordinates("rho theta")
solution = {theta: theta0*exp(sqrt(g/R)*t)}              # linearized about the top
N = m*g*(3*cos(theta) - 2)
leave_angle = Eq(3*cos(theta), 2)
