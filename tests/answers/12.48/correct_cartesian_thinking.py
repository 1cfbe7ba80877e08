# L written from Cartesian velocities of the polar position; dH/dt given as Eq(name, value); equations scaled.
from lagrade.answer import *

m, k, a = parameters("m k a")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
X, Y = r * cos(theta), r * sin(theta)
L = m * (diff(X, t) ** 2 + diff(Y, t) ** 2) / 2 + k * exp(-a * t) / r
H = p_r**2 / (2 * m) + p_theta**2 / (2 * m * r**2) - k * exp(-a * t) / r
hamilton = [
    Eq(m * dot(r), p_r),
    Eq(dot(theta), p_theta / (m * r**2)),
    Eq(m * r**3 * dot(p_r), p_theta**2 - m * k * r * exp(-a * t)),
    dot(p_theta),
]
H_conserved = False
R = Symbol("r")
dH_dt = Eq(Symbol("dHdt"), diff(-k * exp(-a * t) / R, t))  # partial derivative: r held fixed
H_is_E = True
