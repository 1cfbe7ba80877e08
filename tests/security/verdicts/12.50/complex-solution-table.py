# target: solution
# family: complex
# expect: no-credit
# why: every value of the table has an imaginary part 1000*I
from sympy import *

t = symbols("t")
m, k, tau = symbols("m k tau", positive=True)
x = Function("x")(t)

import math


def _rates(s, q, v):
    return v, math.exp(-s)/q**2


def _rk4(q, v, s, h):
    k1 = _rates(s, q, v)
    k2 = _rates(s + h/2, q + h/2*k1[0], v + h/2*k1[1])
    k3 = _rates(s + h/2, q + h/2*k2[0], v + h/2*k2[1])
    k4 = _rates(s + h, q + h*k3[0], v + h*k3[1])
    return q + h/6*(k1[0] + 2*k2[0] + 2*k3[0] + k4[0]), v + h/6*(k1[1] + 2*k2[1] + 2*k3[1] + k4[1])


_q, _v, times, xs = 1.0, 0.0, [0.0], [1.0]
for i in range(1, 501):
    _q, _v = _rk4(_q, _v, (i - 1)*0.01, 0.01)
    if i % 25 == 0:
        times.append(i*0.01)
        xs.append(_q)
solution = {"t": times, "x": [v + 1000*I for v in xs]}
