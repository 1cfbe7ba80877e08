from lagrade.answer import *

m, l, g, a = parameters("m l g a")
theta = coordinates("theta")
g_eff = g + a                      # gravity seen from the accelerating support
eom = [Eq(dot(theta, 2), -g_eff/l*sin(theta))]
period = 2*pi*sqrt(l/g_eff)
