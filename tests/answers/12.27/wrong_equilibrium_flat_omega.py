# expect: equilibrium=partial, omega=incorrect
# The circle at height h with the angular velocity of a flat circle of radius h (no tilt of the normal force):
# the height is right, the angular velocity is not.
from lagrade.answer import *

m, g, h, alpha = parameters("m g h alpha")
z, phi = coordinates("z phi")
equilibrium = {"z": h, "phi_d": sqrt(g / h)}
omega = sqrt(g / h)
