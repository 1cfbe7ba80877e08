# expect: L=incorrect, eom=incorrect, a=incorrect, a_table=incorrect, S_t=incorrect
from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
L = (m + M)*dot(x)**2/2 + m*g*x - M*g*x*cos(alpha)
eom = [Eq((m + M)*dot(x, 2), m*g - M*g*cos(alpha))]
a = g*(m - M*cos(alpha))/(m + M)
a_table = g*(m - M)/(m + M)
S_t = m*M*g*(1 + cos(alpha))/(m + M)
