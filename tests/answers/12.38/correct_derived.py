# H obtained mechanically (Legendre transform done in sympy), Hamilton's equations as differences, reordered.
from lagrade.answer import *

m, k, l0, g = parameters("m k l0 g")
r, theta = coordinates("r theta")
p_r, p_theta = momenta("p_r p_theta")
vr, vth = symbols("v_r v_theta")
Lv = m * (vr**2 + r**2 * vth**2) / 2 + m * g * r * cos(theta) - k * (r - l0)**2 / 2
sol = solve([Eq(p_r, diff(Lv, vr)), Eq(p_theta, diff(Lv, vth))], [vr, vth], dict=True)[0]
H = simplify((p_r * vr + p_theta * vth - Lv).subs(sol))
hamilton = [
    p_theta.diff(t) + m * g * r * sin(theta),
    m * r**3 * p_r.diff(t) - p_theta**2 - m * r**3 * (m * g * cos(theta) - k * (r - l0)),
    m * r**2 * theta.diff(t) - p_theta,
    m * r.diff(t) - p_r,
]
