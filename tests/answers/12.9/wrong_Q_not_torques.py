# expect: L_a=correct, Q_a=partial, eom_a=partial, L_b=correct, eom_b=partial, centrifugal=correct, coriolis=correct
# Q_theta = F_theta and Q_phi = F_phi used in Lagrange's equations (the scale factors r, r*sin(theta) forgotten).
from lagrade.answer import *

m, omega, F_r, F_theta, F_phi = parameters("m omega F_r F_theta F_phi")
r, theta, phi, phip = coordinates("r theta phi phip")
rd, thd, phd, ppd = dot(r), dot(theta), dot(phi), dot(phip)
L_a = m * (rd**2 + r**2 * thd**2 + r**2 * sin(theta) ** 2 * phd**2) / 2
Q_a = {"r": F_r, "theta": F_theta, "phi": F_phi}
eom_a = [
    Eq(m * (dot(r, 2) - r * thd**2 - r * sin(theta) ** 2 * phd**2), F_r),
    Eq(diff(m * r**2 * thd, t) - m * r**2 * sin(theta) * cos(theta) * phd**2, F_theta),
    Eq(diff(m * r**2 * sin(theta) ** 2 * phd, t), F_phi),
]
L_b = m * (rd**2 + r**2 * thd**2 + r**2 * sin(theta) ** 2 * (ppd + omega) ** 2) / 2
w = ppd + omega
eom_b = [
    m * (dot(r, 2) - r * thd**2 - r * sin(theta) ** 2 * w**2) - F_r,
    diff(m * r**2 * thd, t) - m * r**2 * sin(theta) * cos(theta) * w**2 - F_theta,
    diff(m * r**2 * sin(theta) ** 2 * w, t) - F_phi,
]
centrifugal = {"r": m * omega**2 * r * sin(theta) ** 2, "theta": m * omega**2 * r**2 * sin(theta) * cos(theta), "phip": 0}
coriolis = {"r": 2 * m * omega * r * sin(theta) ** 2 * ppd, "theta": 2 * m * omega * r**2 * sin(theta) * cos(theta) * ppd,
            "phip": -2 * m * omega * r * sin(theta) * (rd * sin(theta) + r * cos(theta) * thd)}
