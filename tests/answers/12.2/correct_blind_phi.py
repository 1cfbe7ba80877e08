from lagrade.answer import *

M, R, F = parameters("M R F")
x, phi = coordinates("x phi")
I_c = M*R**2/2
L = M*(R*dot(phi))**2/2 + I_c*dot(phi)**2/2     # x = R*phi
eom = [Eq(Rational(3, 2)*M*R*dot(phi, 2), F)]    # torque F*R on phi, divided by R
a = 2*F/(3*M)
lam = -F/3
