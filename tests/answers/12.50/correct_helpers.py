# V defined first and everything derived from it; dH/dt as the partial derivative of H with x held fixed.
from lagrade.answer import *

m, k, tau = parameters("m k tau")
x, p_x = coordinates("x p_x")
X, P = symbols("x p_x")
V = k * exp(-t / tau) / X
L = m * dot(x) ** 2 / 2 - V.subs(X, x)
H = P**2 / (2 * m) + V
H_conserved = False
dH_dt = diff(H, t)
H_is_E = True
eom = [dot(x, 2) - k * exp(-t / tau) / (m * x**2)]

# the solution as separate lists of times and values
solution = {"t": [0, 1, 2, 3, 4, 5], "x": [1.0, 1.336099, 1.934531, 2.579051, 3.232704, 3.888436]}
