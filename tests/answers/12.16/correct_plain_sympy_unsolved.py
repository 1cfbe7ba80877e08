# Plain sympy, Lagrange's equations exactly as d/dt(dL/dq') - dL/dq = 0; conserved as [E, p_phi] in the other order.
from sympy import Function, cos, diff, sin, symbols

t = symbols("t")
m, R, g = symbols("m R g", positive=True)
theta, phi = Function("theta")(t), Function("phi")(t)
T = m * R**2 / 2 * (theta.diff(t) ** 2 + sin(theta) ** 2 * phi.diff(t) ** 2)
V = -m * g * R * cos(theta)
L = T - V
eom = [diff(diff(L, q.diff(t)), t) - diff(L, q) for q in (theta, phi)]
conserved = [T + V, diff(L, phi.diff(t))]
