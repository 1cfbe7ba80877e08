# target: reaction_angle
# family: fold
# expect: no-credit
# why: atan(mu) times (2/pi)*(atan(1/(20 - mu)) + atan(20 - mu)), which is sign(20 - mu): right for every mu sampled, the wrong sign beyond mu = 20
from sympy import *

mu = symbols("mu", positive=True)
reaction_angle = atan(mu)*(2/pi)*(atan(1/(20 - mu)) + atan(20 - mu))
