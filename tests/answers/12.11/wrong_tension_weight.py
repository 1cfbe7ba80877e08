# expect: L=correct, eom=correct, a=correct, a_table=correct, S_t=incorrect
# S_t: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# Tension taken equal to the hanging weight m*g (true only at rest).
from lagrade.answer import *

m, M, g, alpha = parameters("m M g alpha")
x = coordinates("x")
L = (m + M) * dot(x) ** 2 / 2 + m * g * x - M * g * x * sin(alpha)
eom = [Eq((m + M) * dot(x, 2), g * (m - M * sin(alpha)))]
a = g * (m - M * sin(alpha)) / (m + M)
a_table = m * g / (m + M)
S_t = m * g
