# expect: L=correct, eom=correct, coriolis=correct, centrifugal=correct
# A special case where the book names no force (issue 44): checked for the force it states, L, eom earn full marks.
# L expanded (T_rel + m*omega*(xp*yp' - yp*xp') + centrifugal term) plus d/dt(m*omega*xp*yp);
# eom divided by m and moved to one side, in the other order.
from lagrade.answer import *

m, omega, k = parameters("m omega k")
xp, yp = coordinates("xp yp")
L = (m / 2 * (dot(xp) ** 2 + dot(yp) ** 2) + m * omega * (xp * dot(yp) - yp * dot(xp))
     + m * omega**2 * (xp**2 + yp**2) / 2 - k * (xp**2 + yp**2) / 2
     + m * omega * (dot(xp) * yp + xp * dot(yp)))
eom = [
    dot(yp, 2) + 2 * omega * dot(xp) - omega**2 * yp + k / m * yp,
    dot(xp, 2) - 2 * omega * dot(yp) - (omega**2 - k / m) * xp,
]
coriolis = {"yp": -2 * m * omega * dot(xp), "xp": 2 * m * omega * dot(yp)}
centrifugal = {"xp": m * omega**2 * xp, "yp": m * omega**2 * yp}
