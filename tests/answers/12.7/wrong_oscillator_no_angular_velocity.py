# expect: pendulum=correct, oscillator=incorrect
# (b) Only theta' = 0: a bob held at some angle theta != 0 does not stay there (gravity swings it), so this is not a
# motion the system can keep, and theta is still a coordinate.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
pendulum = {k: oo}
oscillator = {dot(theta): 0}
