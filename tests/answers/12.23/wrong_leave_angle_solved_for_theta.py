# expect: leave_angle=incorrect
# the equation solved for theta, with the factor upside down
from lagrade.answer import *

theta0 = Symbol("theta0")
theta = coordinates("theta")
leave_angle = Eq(theta, asin(3*sin(theta0)/2 / 3))
