# L with the hoop's energy as translation + spin written out; eom solved for the accelerations;
# solution with the denominator written as 2*(M + m) - m*cos(phi)**2.
from lagrade.answer import *

m, M, r_h, g, phi, s0 = parameters("m M r_h g phi s0")
X, s = coordinates("X s")
vx, vy = dot(X) + dot(s) * cos(phi), -dot(s) * sin(phi)
L = M * dot(X) ** 2 / 2 + m * (vx**2 + vy**2) / 2 + m * r_h**2 * (dot(s) / r_h) ** 2 / 2 + m * g * s * sin(phi)
D = 2 * (M + m) - m * cos(phi) ** 2
eom = [Eq(dot(s, 2), (M + m) * g * sin(phi) / D), Eq(dot(X, 2), -m * g * sin(2 * phi) / (2 * D))]
solution = {X: -m * g * sin(phi) * cos(phi) * t**2 / (2 * D), s: s0 + (M + m) * g * sin(phi) * t**2 / (2 * D)}
