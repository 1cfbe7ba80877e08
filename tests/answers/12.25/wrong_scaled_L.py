# expect: L=partial, a=correct
# L: extra (the book does not ask it): wrong here: shown, not counted in the score (issue 33), still a wrong answer.
# L multiplied by 2 (T written without the 1/2's): right equations, wrong normalization.
from lagrade.answer import *

M, R, g, theta = parameters("M R g theta")
s = coordinates("s")
L = Rational(7, 5) * M * dot(s) ** 2 + 2 * M * g * s * sin(theta)
a = 5 * g * sin(theta) / 7
