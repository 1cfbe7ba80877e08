# expect: L_b=incorrect, eom_b=incorrect, solution_b=incorrect, L_a=missing
# Formulation b (y) as a sliding block: the rotational energy forgotten. Right in neither formulation; the
# y answer cannot be read in theta, so its feedback is formulation b's (the named mistake for the block).
from lagrade.answer import *

M, R, g, l, phi = parameters("M R g l phi")
y0, v0 = symbols("y0 v0")
y = coordinates("y")
L = M / 2 * dot(y) ** 2 - M * g * (l - y) * sin(phi)
eom = [Eq(dot(y, 2), g * sin(phi))]
solution = {y: y0 + v0 * t + g * sin(phi) * t**2 / 2}
