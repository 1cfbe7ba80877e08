# L plus total time derivatives and constants, cos written with a half-angle identity, eom as expressions = 0.
from lagrade.answer import *

m, g, k, l, h = parameters("m g k l h")
y, theta = coordinates("y theta")

# (a) adds y*y' = d/dt(y**2/2) and a constant
L_a = Rational(1, 2) * m * dot(y) ** 2 - m * g * y + y * dot(y) + 7
eom_a = [dot(y, 2) + g]

# (b) complete the square: V = k (y - m g/k)^2 / 2 differs from k y^2/2 - m g y by a constant
L_b = m * dot(y) ** 2 / 2 - k * (y - m * g / k) ** 2 / 2
eom_b = [k * y - m * g + m * dot(y, 2)]

# (c) cos(theta) = 1 - 2 sin^2(theta/2); height measured from the lowest point
L_c = m * l**2 * dot(theta) ** 2 / 2 - m * g * l * 2 * sin(theta / 2) ** 2
eom_c = [l * dot(theta, 2) + g * sin(theta)]

# (d) parallel-axis theorem, plus d/dt(theta * t)
I_O = m * (l**2 + 12 * h**2) / 12
L_d = I_O * dot(theta) ** 2 / 2 + m * g * h * cos(theta) + diff(theta * t, t)
eom_d = [Eq(-(l**2 + 12 * h**2) * dot(theta, 2), 12 * g * h * sin(theta))]
