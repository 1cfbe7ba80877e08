# H written out by hand with the determinant m*l**2*(M + m*sin(theta)**2); cyclic given as the coordinate object; conserved as p_X.
from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X, p_theta = momenta("p_X p_theta")

L = (M + m) / 2 * dot(X) ** 2 + m * l * cos(theta) * dot(X) * dot(theta) + m * l**2 / 2 * dot(theta) ** 2 \
    + m * g * l * cos(theta)
H = (m * l**2 * p_X**2 - 2 * m * l * cos(theta) * p_X * p_theta + (M + m) * p_theta**2) \
    / (2 * m * l**2 * (M + m * (1 - cos(theta) ** 2))) - m * g * l * cos(theta)
cyclic = [X]
conserved = [p_X]
omega = sqrt(g / l * (1 + m / M))

# (b) X eliminated: theta'' solved
eom_reduced = Eq(dot(theta, 2), -((M + m) * g * sin(theta) + m * l * sin(theta) * cos(theta) * dot(theta) ** 2)
                 / (l * (M + m * sin(theta) ** 2)))
