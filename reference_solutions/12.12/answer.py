"""Problem 12.12: particle on a smooth plane turning about its lower edge, theta = omega t.

Position (r cos(wt), r sin(wt)): v^2 = r'^2 + w^2 r^2, V = m g r sin(wt).
r'' = w^2 r - g sin(wt). Homogeneous: cosh, sinh(wt); particular: A sin(wt) with -A w^2 = w^2 A - g,
A = g/(2 w^2). Initial values fix r = r0 cosh + (v0/w - g/(2 w^2)) sinh + g sin/(2 w^2).
H = p^2/2m - m w^2 r^2/2 + m g r sin(wt) depends on t explicitly: not conserved.
"""
from sympy import Eq, Function, cosh, sin, sinh, symbols

t = symbols("t")
m, g, omega, r0, v0 = symbols("m g omega r0 v0", positive=True)
r = Function("r")(t)

L = m * (r.diff(t) ** 2 + omega**2 * r**2) / 2 - m * g * r * sin(omega * t)
eom = [Eq(r.diff(t, 2), omega**2 * r - g * sin(omega * t))]
solution = {"r": r0 * cosh(omega * t) + (v0 / omega - g / (2 * omega**2)) * sinh(omega * t)
            + g * sin(omega * t) / (2 * omega**2)}
H_conserved = False
