# leave_angle as the equation it satisfies (3 sin(theta) = 2 sin(theta0)); L scaled-free but with a constant added;
# eom unsolved and multiplied by 6/(M*l); N_w expanded.
from lagrade.answer import *

M, l, g = parameters("M l g")
theta0 = Symbol("theta0")
theta = coordinates("theta")
thd = dot(theta)
L = Rational(1, 2) * (M * l**2 / 4 + M * l**2 / 12) * thd**2 - M * g * l / 2 * sin(theta) + 5 * M * g * l
eom = 2 * l * dot(theta, 2) + 3 * g * cos(theta)
N_w = 3 * M * g * sin(theta) * cos(theta) / 4 - M * l * cos(theta) * thd**2 / 2
leave_angle = Eq(3 * sin(theta), 2 * sin(theta0))
