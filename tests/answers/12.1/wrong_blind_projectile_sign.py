# expect: L_a=incorrect, eom_a=incorrect
from lagrade.answer import *

m, g = parameters("m g")
y = coordinates("y")
L_a = m*dot(y)**2/2 + m*g*y
eom_a = [Eq(dot(y, 2), g)]
