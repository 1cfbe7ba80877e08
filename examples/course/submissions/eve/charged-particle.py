# Right L, but H in the momenta m*v (no q*A), and the eom of the field along -z.
from lagrade.answer import *

m, q, B = parameters("m q B")
x, y, z = coordinates("x y z")
p_x, p_y, p_z = momenta("p_x p_y p_z")

L = m*(dot(x)**2 + dot(y)**2 + dot(z)**2)/2 + q*B*(x*dot(y) - y*dot(x))/2
eom = [Eq(dot(x, 2), -q*B/m*dot(y)), Eq(dot(y, 2), q*B/m*dot(x)), Eq(dot(z, 2), 0)]
H = (p_x**2 + p_y**2 + p_z**2)/(2*m)
omega = q*B/m
