# expect: H=incorrect, hamilton=partial
# p_theta taken as m theta' (r^2 forgotten): H has p_theta^2/(2m) and the centrifugal term disappears.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
H = p_r**2 / (2 * m) + p_theta**2 / (2 * m) - m * g * r * cos(theta) + k * (r - l0)**2 / 2
hamilton = [
    Eq(r.diff(t), p_r / m),
    Eq(theta.diff(t), p_theta / m),
    Eq(p_r.diff(t), m * g * cos(theta) - k * (r - l0)),
    Eq(p_theta.diff(t), -m * g * r * sin(theta)),
]
