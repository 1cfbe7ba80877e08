from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
T = (m + M)*dot(x)**2/2
V = -m*g*x + M*g*x*sin(alpha)       # M rises x*sin(alpha) while m falls x
L = T - V
eom = [Eq((m + M)*dot(x, 2), m*g - M*g*sin(alpha))]
a = g*(m - M*sin(alpha))/(m + M)
a_table = a.subs(alpha, 0)
S_t = m*(g - a)
