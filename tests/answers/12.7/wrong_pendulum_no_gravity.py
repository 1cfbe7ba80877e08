# expect: pendulum=incorrect, oscillator=correct
# (a) "switch off gravity" read as the condition: with g -> 0 there is no pendulum left at all.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
pendulum = {g: 0}
oscillator = {theta: 0}
