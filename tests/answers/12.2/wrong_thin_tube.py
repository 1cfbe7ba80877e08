# expect: L=incorrect, eom=incorrect, a=incorrect, lam=incorrect
# Moment of inertia of a thin tube (M*R**2) used for the solid cylinder.
from lagrade.answer import *

M, R, F = parameters("M R F")
phi = coordinates("phi")
L = M * R**2 * phi.diff(t) ** 2
eom = [Eq(2 * M * R**2 * phi.diff(t, 2), F * R)]
a = F / (2 * M)
lam = -F / 2
