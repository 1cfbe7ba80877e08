from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
T = m*(dot(r)**2 + r**2*dot(theta)**2)/2
V = -m*g*r*cos(theta) + k*(r - l0)**2/2
L = T - V
eom = [Eq(dot(r, 2), r*dot(theta)**2 + g*cos(theta) - k*(r - l0)/m),
       Eq(dot(theta, 2), -(2*dot(r)*dot(theta) + g*sin(theta))/r)]
omega = sqrt(k/m)

# (a) the spring does not stretch: k -> oo; (b) no swing at all: theta = 0 for all time
pendulum = {k: oo}
oscillator = {theta: 0, dot(theta): 0}
