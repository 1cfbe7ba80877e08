# expect: L=correct, eom=correct, N=incorrect, leave_angle=incorrect
# Energy from the top without the factor 2: (R + r_s) theta'^2 = g (1 - cos theta), so N = m g (2 cos - 1).
from lagrade.answer import *

m, R, r_s, g = parameters("m R r_s g")
theta = coordinates("theta")
L = m * (R + r_s)**2 * dot(theta)**2 / 2 - m * g * (R + r_s) * cos(theta)
eom = [Eq(theta.diff(t, 2), g * sin(theta) / (R + r_s))]
lam = m * g * cos(theta) - m * (R + r_s) * dot(theta)**2
N = m * g * (2 * cos(theta) - 1)
leave_angle = pi / 3
