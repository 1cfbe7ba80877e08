# expect: L=incorrect, eom=incorrect, coriolis=incorrect, centrifugal=correct
# Rotation sense reversed in the velocity (xp' + omega*yp, yp' - omega*xp): Coriolis force flips sign.
from lagrade.answer import *

m, omega, k = parameters("m omega k")
xp, yp = coordinates("xp yp")
L = m / 2 * ((dot(xp) + omega * yp) ** 2 + (dot(yp) - omega * xp) ** 2) - k * (xp**2 + yp**2) / 2
eom = [
    Eq(m * dot(xp, 2), -k * xp - 2 * m * omega * dot(yp) + m * omega**2 * xp),
    Eq(m * dot(yp, 2), -k * yp + 2 * m * omega * dot(xp) + m * omega**2 * yp),
]
coriolis = {"xp": -2 * m * omega * dot(yp), "yp": 2 * m * omega * dot(xp)}
centrifugal = {"xp": m * omega**2 * xp, "yp": m * omega**2 * yp}
