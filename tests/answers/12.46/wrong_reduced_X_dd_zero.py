# expect: eom_reduced=incorrect
# (b) "X is cyclic, so X'' = 0" put into the theta equation: that holds X fixed; it is p_X that is constant.
from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X = symbols("p_X")
eom_reduced = Eq(l * dot(theta, 2) + g * sin(theta), 0)
