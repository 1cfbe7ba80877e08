# expect: N=incorrect, leave_angle=incorrect, solution=correct
# Uses the static normal force m*g*cos(theta) (no centripetal term), so concludes the particle leaves at theta = pi/2.
from lagrade.answer import *

m, R, g, theta0 = parameters("m R g theta0")
theta = symbols("theta")
solution = {"theta": 4 * atan(tan(theta0 / 4) * exp(sqrt(g / R) * t))}
N = m * g * cos(theta)
leave_angle = pi / 2
