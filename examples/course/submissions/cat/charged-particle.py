# The force written q*B x v instead of q*v x B; the Larmor frequency.
from lagrade.answer import *

m, q, B = parameters("m q B")
x, y, z = coordinates("x y z")
p_x, p_y, p_z = momenta("p_x p_y p_z")

L = m*(dot(x)**2 + dot(y)**2 + dot(z)**2)/2 + q*B*(x*dot(y) - y*dot(x))/2
eom = [Eq(m*dot(x, 2), -q*B*dot(y)), Eq(m*dot(y, 2), q*B*dot(x)), Eq(dot(z, 2), 0)]
H = ((p_x + q*B*y/2)**2 + (p_y - q*B*x/2)**2 + p_z**2)/(2*m)
omega = q*B/(2*m)
