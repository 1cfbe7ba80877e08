# expect: L=incorrect, a=incorrect
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = M*dot(s)**2/2 + (M*R**2/2)*(dot(s)/R)**2/2 + M*g*s*sin(theta)
a = 2*g*sin(theta)/3
