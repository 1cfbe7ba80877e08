# expect: L=incorrect, eom=incorrect, eom_small=incorrect, theta_p=incorrect
# Support velocity taken as +a*omega*sin(omega*t): the driving term changes sign.
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
thd = dot(theta)
L = m * (l**2 * thd**2 + 2 * a * omega * l * sin(omega * t) * cos(theta) * thd) / 2 + m * g * l * cos(theta)
eom = [Eq(l * dot(theta, 2) + g * sin(theta), -a * omega**2 * cos(omega * t) * cos(theta))]
eom_small = [Eq(dot(theta, 2) + g / l * theta, -a * omega**2 / l * cos(omega * t))]
omega0 = sqrt(g / l)
theta_p = -a * omega**2 * cos(omega * t) / (g - l * omega**2)
H_conserved = False
H_is_E = False
