# The physical components along e_r, e_theta, e_phi for (b): with the equations of (a) written with F_r,
# F_theta, F_phi (as the catalogue writes them), the extra terms are these components; the book lets the
# student compare either way, so both normalizations are accepted.
from lagrade.answer import *

m, omega, F_r, F_theta, F_phi = parameters("m omega F_r F_theta F_phi")
r, theta, phi, phip = coordinates("r theta phi phip")
rd, thd, phd, ppd = dot(r), dot(theta), dot(phi), dot(phip)
L_a = m * (rd**2 + r**2 * thd**2 + r**2 * sin(theta) ** 2 * phd**2) / 2
Q_a = {"r": F_r, "theta": r * F_theta, "phi": r * sin(theta) * F_phi}
eom_a = [
    Eq(m * (dot(r, 2) - r * thd**2 - r * sin(theta) ** 2 * phd**2), F_r),
    Eq(m * (r * dot(theta, 2) + 2 * rd * thd - r * sin(theta) * cos(theta) * phd**2), F_theta),
    Eq(m * (r * sin(theta) * dot(phi, 2) + 2 * rd * sin(theta) * phd + 2 * r * cos(theta) * thd * phd), F_phi),
]
L_b = m * (rd**2 + r**2 * thd**2 + r**2 * sin(theta) ** 2 * (ppd + omega) ** 2) / 2
centrifugal = {"r": m * omega**2 * r * sin(theta) ** 2, "theta": m * omega**2 * r * sin(theta) * cos(theta), "phip": 0}
coriolis = {"r": 2 * m * omega * r * sin(theta) ** 2 * ppd, "theta": 2 * m * omega * r * sin(theta) * cos(theta) * ppd,
            "phip": -2 * m * omega * (rd * sin(theta) + r * cos(theta) * thd)}
eom_b = [
    Eq(m * (dot(r, 2) - r * thd**2 - r * sin(theta) ** 2 * ppd**2), F_r + centrifugal["r"] + coriolis["r"]),
    Eq(m * (r * dot(theta, 2) + 2 * rd * thd - r * sin(theta) * cos(theta) * ppd**2),
       F_theta + centrifugal["theta"] + coriolis["theta"]),
    Eq(m * (r * sin(theta) * dot(phip, 2) + 2 * rd * sin(theta) * ppd + 2 * r * cos(theta) * thd * ppd),
       F_phi + coriolis["phip"]),
]
