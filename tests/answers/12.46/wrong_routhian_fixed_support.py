# expect: eom_reduced=incorrect
# (b) The Routhian taken as the Lagrangian of a pendulum on a fixed support (the car's recoil dropped).
from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X = symbols("p_X")
routhian = m * l**2 * dot(theta) ** 2 / 2 + m * g * l * cos(theta)
