from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L = m*dot(x1)**2/2 + m*dot(x2)**2/2 - k*x1**2 + k*x1*x2 - k*x2**2/2
eom = [Eq(dot(x1, 2), (-2*k*x1 + k*x2)/m), Eq(dot(x2, 2), k*(x1 - x2)/m)]
