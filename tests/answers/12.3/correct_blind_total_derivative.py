from lagrade.answer import *

m, k = parameters("m k")
x1, x2 = coordinates("x1 x2")
L0 = m*(dot(x1)**2 + dot(x2)**2)/2 - k*x1**2/2 - k*(x2 - x1)**2/2
L = L0 + dot(x1)*x2 + x1*dot(x2) + 3*t        # + d/dt(x1*x2 + 3*t**2/2)
eom = [Eq(m*dot(x1, 2) + 2*k*x1 - k*x2, 0), Eq(m*dot(x2, 2) - k*x1 + k*x2, 0)]
