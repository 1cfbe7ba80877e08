# expect: L=incorrect, eom=partial, solution=incorrect
# Forgot that the hoop rides on the moving wedge (no cross term): the wedge never recoils.
from lagrade.answer import *

m, M, r_h, g, phi, s0 = parameters("m M r_h g phi s0")
X, s = coordinates("X s")
L = M / 2 * dot(X) ** 2 + m * dot(s) ** 2 + m * g * s * sin(phi)
eom = [Eq(M * dot(X, 2), 0), Eq(2 * dot(s, 2) + cos(phi) * dot(X, 2), g * sin(phi))]
solution = {X: 0, s: s0 + g * sin(phi) * t**2 / 4}
