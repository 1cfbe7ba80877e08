from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = momenta("p_x")
V = k*exp(-t/tau)/x
L = m*dot(x)**2/2 - V
H = p_x**2/(2*m) + V
H_conserved = False
dH_dt = -V/tau          # partial derivative of H in t
H_is_E = True
eom = [Eq(m*dot(x, 2), k*exp(-t/tau)/x**2)]

# the solution as rows [t, x] (x to 6 decimals, from an accurate integration)
solution = [[0.0, 1.0], [0.5, 1.103241], [1.0, 1.336099], [1.5, 1.62401], [2.0, 1.934531], [2.5, 2.254659],
            [3.0, 2.579051], [3.5, 2.905409], [4.0, 3.232704], [4.5, 3.560456], [5.0, 3.888436]]
