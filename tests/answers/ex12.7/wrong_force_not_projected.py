# expect: H=correct, hamilton=partial, cyclic=correct, conserved=correct
# -dH/dx taken as -k/r^2 for both components: the radial force k/r^2 not projected onto x and y (x/r, y/r missing).
from lagrade.answer import *

m, k = parameters("m k")
x, y = coordinates("x y")
p_x, p_y = momenta("p_x p_y")
r = sqrt(x**2 + y**2)
H = (p_x**2 + p_y**2) / (2 * m) - k / r
hamilton = [Eq(x.diff(t), p_x / m), Eq(y.diff(t), p_y / m),
            Eq(p_x.diff(t), -k / r**2), Eq(p_y.diff(t), -k / r**2)]
cyclic = []
conserved = [m * (x * y.diff(t) - y * x.diff(t)), m * (x.diff(t)**2 + y.diff(t)**2) / 2 - k / r]
