# expect: L=incorrect, solution=incorrect
from lagrade.answer import *

m, M, r_h, g, phi = parameters("m M r_h g phi")
s0 = symbols("s0")
X, s = coordinates("X s")
L = (M + m)*dot(X)**2/2 + m*cos(phi)*dot(X)*dot(s) + m*dot(s)**2/2 + m*g*s*sin(phi)
eom = [Eq((M + m)*dot(X, 2) + m*cos(phi)*dot(s, 2), 0),
       Eq(dot(s, 2) + cos(phi)*dot(X, 2), g*sin(phi))]
a_s = g*(M + m)*sin(phi)/(M + m*sin(phi)**2)
a_X = -m*cos(phi)*a_s/(M + m)
solution = {X: a_X*t**2/2, s: s0 + a_s*t**2/2}
