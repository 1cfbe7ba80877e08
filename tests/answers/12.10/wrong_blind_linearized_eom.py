# expect: eom=incorrect, period=correct
from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
g_eff = g + a
eom = [Eq(dot(theta, 2), -g_eff/l*theta)]   # small-angle form; the part asks the equation of motion
period = 2*pi*sqrt(l/g_eff)
