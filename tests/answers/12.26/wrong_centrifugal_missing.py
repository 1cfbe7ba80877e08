# expect: L=incorrect, eom=incorrect, coriolis=correct, centrifugal=incorrect
# Kept only the linear-in-omega cross term (dropped the omega**2 part of T): centrifugal force missing,
# and the centrifugal force given pointing inward.
from lagrade.answer import *

m, omega, k = parameters("m omega k")
xp, yp = coordinates("xp yp")
L = m / 2 * (dot(xp) ** 2 + dot(yp) ** 2) + m * omega * (xp * dot(yp) - yp * dot(xp)) - k * (xp**2 + yp**2) / 2
eom = [
    Eq(m * dot(xp, 2), -k * xp + 2 * m * omega * dot(yp)),
    Eq(m * dot(yp, 2), -k * yp - 2 * m * omega * dot(xp)),
]
coriolis = {"xp": 2 * m * omega * dot(yp), "yp": -2 * m * omega * dot(xp)}
centrifugal = {"xp": -m * omega**2 * xp, "yp": -m * omega**2 * yp}
