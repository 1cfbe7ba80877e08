# expect: L=correct, eom=correct, theta_p=incorrect, H_is_E=incorrect, H_conserved=correct
# H taken to be T + V (it is T2 - T0 + V here), and the particular solution without the omega**2 of the
# support's acceleration.
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
thd = dot(theta)
L = m * (l**2 * thd**2 - 2 * a * omega * l * sin(omega * t) * cos(theta) * thd
         + a**2 * omega**2 * sin(omega * t) ** 2) / 2 + m * g * l * cos(theta)
eom = [Eq(dot(theta, 2), -g / l * sin(theta) + a * omega**2 / l * cos(omega * t) * cos(theta))]
omega0 = sqrt(g / l)
theta_p = a * cos(omega * t) / (g - l * omega**2)
H_conserved = False
H_is_E = True
