# expect: R_r=incorrect, R_theta=incorrect, R_z=incorrect
# Reaction taken as just balancing the attraction (the bead treated as if at rest).
from lagrade.answer import *

m, a, k, c = parameters("m a k c")
theta = coordinates("theta")
R_r = c * a
R_theta = 0
R_z = c * k * theta
