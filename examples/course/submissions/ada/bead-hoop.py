# Right, in unusual forms: L plus a total time derivative, the eom multiplied out and moved
# across, H in cos(2*theta), the equilibrium as an equation.
from sympy import *

t = symbols("t")
m, R, g, omega = symbols("m R g omega", positive=True)
theta = Function("theta")(t)
p = Function("p_theta")(t)

L = m*R**2*theta.diff(t)**2/2 + m*R**2*omega**2*(1 - cos(2*theta))/4 + m*g*R*cos(theta) \
    + diff(m*g*R*sin(theta), t)
eom = [m*R**2*theta.diff(t, 2) + m*g*R*sin(theta) - m*R**2*omega**2*sin(2*theta)/2]
H = p**2/(2*m*R**2) - m*R**2*omega**2*(1 - cos(2*theta))/4 - m*g*R*cos(theta)
equilibrium = Eq(omega**2*R*cos(theta), g)
