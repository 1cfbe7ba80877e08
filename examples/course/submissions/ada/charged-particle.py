# Right, in the Landau gauge A = (-B*y, 0, 0): L, its H, the eom as expressions equal to zero, and
# the frequency with |q|.
from lagrade.answer import *

m, q, B = parameters("m q B")
x, y, z = coordinates("x y z")
p_x, p_y, p_z = momenta("p_x p_y p_z")

L = m*(dot(x)**2 + dot(y)**2 + dot(z)**2)/2 - q*B*y*dot(x)
eom = [m*dot(x, 2) - q*B*dot(y), dot(y, 2) + q*B/m*dot(x), dot(z, 2)]
H = ((p_x + q*B*y)**2 + p_y**2 + p_z**2)/(2*m)
omega = Abs(q)*B/m
