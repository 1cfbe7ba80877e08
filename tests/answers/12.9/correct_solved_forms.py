# Equations divided through / solved for the accelerations; eom given in Lagrange form d/dt(dL/dq') - dL/dq = Q.
from lagrade.answer import *

m, omega, F_r, F_theta, F_phi = parameters("m omega F_r F_theta F_phi")
r, theta, phi, phip = coordinates("r theta phi phip")
rd, thd, phd, ppd = dot(r), dot(theta), dot(phi), dot(phip)
L_a = m * (rd**2 + r**2 * thd**2 + (r * sin(theta) * phd) ** 2) / 2 + 7
Q_a = {r: F_r, theta: F_theta * r, phi: F_phi * r * sin(theta)}
eom_a = [
    Eq(dot(r, 2), r * thd**2 + r * sin(theta) ** 2 * phd**2 + F_r / m),
    Eq(diff(m * r**2 * thd, t) - m * r**2 * sin(theta) * cos(theta) * phd**2, r * F_theta),
    Eq(diff(m * r**2 * sin(theta) ** 2 * phd, t), r * sin(theta) * F_phi),
]
L_b = m * (rd**2 + r**2 * thd**2 + r**2 * sin(theta) ** 2 * (ppd**2 + 2 * omega * ppd + omega**2)) / 2
w = ppd + omega
eom_b = [
    m * (dot(r, 2) - r * thd**2 - r * sin(theta) ** 2 * w**2) - F_r,
    m * (r * dot(theta, 2) + 2 * rd * thd - r * sin(theta) * cos(theta) * w**2) - F_theta,
    m * (r * sin(theta) * dot(phip, 2) + 2 * rd * sin(theta) * w + 2 * r * cos(theta) * thd * w) - F_phi,
]
# the generalized forces written with other trig forms: torques for the angles
centrifugal = {"r": m * omega**2 * r * (1 - cos(theta) ** 2), "theta": m * omega**2 * r**2 * sin(2 * theta) / 2, "phip": 0}
coriolis = {r: 2 * m * omega * r * sin(theta) ** 2 * ppd, theta: m * omega * r**2 * sin(2 * theta) * ppd,
            phip: -m * omega * (2 * r * rd * sin(theta) ** 2 + r**2 * sin(2 * theta) * thd)}
