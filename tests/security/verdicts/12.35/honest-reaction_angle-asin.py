# target: reaction_angle
# family: honest
# expect: full-marks
# why: nothing: asin(mu/sqrt(1 + mu**2)) is atan(mu) for every mu (both in [-pi/2, pi/2], equal sines)
from sympy import *

mu = symbols("mu", positive=True)
reaction_angle = asin(mu/sqrt(1 + mu**2))
