# expect: N_w=incorrect, leave_angle=incorrect
# Wall force taken from statics (no centripetal term), and the leave condition from cos(theta) = 2/3*cos(theta0)
# (angle confused with the one from the wall).
from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = Symbol("theta0")
theta = coordinates("theta")
N_w = 3 * M * g * sin(theta) * cos(theta) / 4
leave_angle = acos(2 * cos(theta0) / 3)
