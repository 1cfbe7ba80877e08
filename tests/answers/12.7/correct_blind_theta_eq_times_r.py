from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
L = m*(dot(r)**2 + r**2*dot(theta)**2)/2 + m*g*r*cos(theta) - k*(r - l0)**2/2
eom = [(dot(r, 2) - r*dot(theta)**2 - g*cos(theta))*m + k*(r - l0),
       Eq(dot(theta, 2)*r**2, -r*(2*dot(r)*dot(theta) + g*sin(theta)))]   # theta-equation times r (nonzero)
omega = 1/sqrt(m/k)

# (a) the static stretch m*g/k small against l0; (b) the bob moves along the vertical only
pendulum = {m * g / (k * l0): 0}
oscillator = [Eq(theta, 0)]
