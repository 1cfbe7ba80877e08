# expect: dof=incorrect, cyclic=partial, conserved=partial
# Four degrees of freedom counted (the planar count, but the masses move freely through space); r called cyclic too (it appears in H); the energy not listed.
from lagrade.answer import *

m1, m2, k, l0 = parameters("m1 m2 k l0")
X, Y, Z, r, theta = coordinates("X Y Z r theta")
mu = m1 * m2 / (m1 + m2)
dof = 4
cyclic = ["X", "Y", "Z", "theta", "r"]
conserved = [(m1 + m2) * dot(X), (m1 + m2) * dot(Y), (m1 + m2) * dot(Z), mu * r**2 * dot(theta)]
