# L without the velocity-free term a**2*omega**2*sin(omega*t)**2 and with the cross term integrated by parts
# (-m*a*omega*l*sin(omega*t)*cos(theta)*theta' = d/dt(-m*a*omega*l*sin(omega*t)*sin(theta)) + m*a*omega**2*l*cos(omega*t)*sin(theta)),
# eom multiplied by m*l, small-angle equation multiplied by l.
from lagrade.answer import *

m, l, g, a, omega = parameters("m l g a omega")
theta = coordinates("theta")
thd = dot(theta)
L = m * l**2 * thd**2 / 2 + m * a * omega**2 * l * cos(omega * t) * sin(theta) + m * g * l * cos(theta)
eom = [m * l**2 * dot(theta, 2) + m * g * l * sin(theta) - m * a * omega**2 * l * cos(omega * t) * cos(theta)]
eom_small = [Eq(l * dot(theta, 2), a * omega**2 * cos(omega * t) - g * theta)]
omega0 = 1 / sqrt(l / g)
theta_p = -a * omega**2 * cos(omega * t) / (l * omega**2 - g)
H_conserved = False
H_is_E = False
