# expect: solution=incorrect, N=correct, leave_angle=correct
# theta(t) with exp(-sqrt(g/R)*t): a solution of the equation of motion, but it climbs back to the top instead of falling away.
from lagrade.answer import *

m, R, g, theta0 = parameters("m R g theta0")
theta = symbols("theta")
solution = {"theta": 4 * atan(tan(theta0 / 4) * exp(-sqrt(g / R) * t))}
N = m * g * (3 * cos(theta) - 2)
leave_angle = atan(sqrt(5) / 2)
