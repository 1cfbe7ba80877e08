# expect: L=correct, eom=correct, a=correct, a_table=incorrect, S_t=correct
from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
L = (m + M)*dot(x)**2/2 + m*g*x - M*g*x*sin(alpha)
eom = [(m + M)*dot(x, 2) - m*g + M*g*sin(alpha)]
a = g*(m - M*sin(alpha))/(m + M)
a_table = M*g/(m + M)
S_t = m*M*g*(1 + sin(alpha))/(m + M)
