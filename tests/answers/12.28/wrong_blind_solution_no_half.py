# expect: L=correct, eom=correct, solution=incorrect
from lagrade.answer import *

m, M, r_h, g, phi = parameters("m M r_h g phi")
s0 = symbols("s0")
X, s = coordinates("X s")
L = (M + m)*dot(X)**2/2 + m*cos(phi)*dot(X)*dot(s) + m*dot(s)**2 + m*g*s*sin(phi)
eom = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (X, s)]
den = 2*(M + m) - m*cos(phi)**2
a_s = g*(M + m)*sin(phi)/den
solution = {"X": -m*cos(phi)*a_s/(M + m)*t**2, "s": s0 + a_s*t**2}
