# expect: L=incorrect, eom=incorrect, coriolis=incorrect, centrifugal=incorrect
# Wrote T with the relative velocity only: no Coriolis and no centrifugal terms at all.
from lagrade.answer import *

m, omega, k = parameters("m omega k")
xp, yp = coordinates("xp yp")
L = m / 2 * (dot(xp) ** 2 + dot(yp) ** 2) - k * (xp**2 + yp**2) / 2
eom = [Eq(m * dot(xp, 2), -k * xp), Eq(m * dot(yp, 2), -k * yp)]
coriolis = {"xp": 0, "yp": 0}
centrifugal = {"xp": 0, "yp": 0}
