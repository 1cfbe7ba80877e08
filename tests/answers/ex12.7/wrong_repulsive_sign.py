# expect: H=incorrect, hamilton=partial, cyclic=correct, conserved=partial
# Sign of V flipped (V = +k/r): the force on the particle points away from the centre.
from lagrade.answer import *

m, k = parameters("m k")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
r = sqrt(x**2 + y**2)
H = (p_x**2 + p_y**2) / (2 * m) + k / r
hamilton = [Eq(x.diff(t), p_x / m), Eq(y.diff(t), p_y / m),
            Eq(p_x.diff(t), k * x / r**3), Eq(p_y.diff(t), k * y / r**3)]
cyclic = []
conserved = [m * (x * y.diff(t) - y * x.diff(t)), m * (x.diff(t)**2 + y.diff(t)**2) / 2 + k / r]
