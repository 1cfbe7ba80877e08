from lagrade.answer import *

m, M, r_h, g, phi = parameters("m M r_h g phi")
s0 = symbols("s0")
X, s = coordinates("X s")
vx = dot(X) + dot(s)*cos(phi)
vy = -dot(s)*sin(phi)
T = M*dot(X)**2/2 + m*(vx**2 + vy**2)/2 + m*r_h**2*(dot(s)/r_h)**2/2
L = T + m*g*s*sin(phi)
eom = [Eq((M + m)*dot(X, 2) + m*cos(phi)*dot(s, 2), 0),
       Eq(2*m*dot(s, 2) + m*cos(phi)*dot(X, 2), m*g*sin(phi))]
den = 2*(M + m) - m*cos(phi)**2
a_s = g*(M + m)*sin(phi)/den
a_X = -m*cos(phi)*a_s/(M + m)
solution = {X: a_X*t**2/2, s: s0 + a_s*t**2/2}
