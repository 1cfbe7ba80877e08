# A gauge of its own: L' = L_ground + dF/dt with F = m*a0*t*x - m*g*t*x (a student who moved part of the
# linear terms into a total derivative). Its momentum is p_x = m*(x' - a0*t) + m*(a0 - g)*t and
# H' = H_ground(x, p_x - dF/dx) - dF/dt; Hamilton's equations of H'. H_conserved and H_is_E are then judged in
# the ground frame (no answer is stated for another gauge): H' depends on t explicitly, and is not T + V.
from lagrade.answer import *

m, k, g, a0, l0 = parameters("m k g a0 l0")
x, p_x = coordinates("x p_x")
X, P = symbols("X P")
H_ground = P**2 / (2 * m) + a0 * t * P + k * X**2 / 2 + m * g * (a0 * t**2 / 2 - l0 - X)
F = m * a0 * t * X - m * g * t * X
H_gauge = H_ground.subs(P, P - diff(F, X)) - diff(F, t)
H = H_gauge.subs({X: x, P: p_x})
hamilton = [Eq(dot(x), diff(H_gauge, P).subs({X: x, P: p_x})), Eq(dot(p_x), -diff(H_gauge, X).subs({X: x, P: p_x}))]
H_conserved = False
H_is_E = False
L = m * (a0 * t - dot(x)) ** 2 / 2 - k * x**2 / 2 - m * g * (a0 * t**2 / 2 - l0 - x) + diff(F.subs(X, x), t)
eom = [Eq(dot(x, 2), g + a0 - k * x / m)]
period = 2 * pi * sqrt(m / k)
