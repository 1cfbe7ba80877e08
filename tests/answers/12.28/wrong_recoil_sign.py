# expect: L=incorrect, eom=incorrect, solution=partial
# Sign of the cross term wrong (hoop velocity taken as X' - s'*cos(phi) with X along the down-slope projection).
from lagrade.answer import *

m, M, r_h, g, phi, s0 = parameters("m M r_h g phi s0")
X, s = coordinates("X s")
L = (M + m) / 2 * dot(X) ** 2 - m * cos(phi) * dot(X) * dot(s) + m * dot(s) ** 2 + m * g * s * sin(phi)
eom = [Eq((M + m) * dot(X, 2) - m * cos(phi) * dot(s, 2), 0), Eq(2 * dot(s, 2) - cos(phi) * dot(X, 2), g * sin(phi))]
D = 2 * M + m + m * sin(phi) ** 2
solution = {X: m * g * sin(phi) * cos(phi) * t**2 / (2 * D), s: s0 + (M + m) * g * sin(phi) * t**2 / (2 * D)}
