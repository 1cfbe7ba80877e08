# N left unsimplified (m g cos - centripetal, with the energy equation substituted); angle as asin; leave condition as N = 0.
from sympy import Eq, Function, Symbol, asin, atan, cos, exp, sqrt, symbols, tan

t = Symbol("t")
m, R, g, theta0 = symbols("m R g theta0", positive=True)
th = symbols("theta")

v2 = 2 * g * R * (1 - cos(th))          # energy conservation from rest at the top
N = m * g * cos(th) - m * v2 / R
leave_angle = Eq(m * g * cos(th) - m * v2 / R, 0)
solution = {"theta": 2 * (2 * atan(tan(theta0 / 4) * exp(t * sqrt(g) / sqrt(R))))}
