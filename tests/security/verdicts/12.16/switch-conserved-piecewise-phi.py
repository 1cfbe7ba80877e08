# target: conserved
# family: switch
# expect: no-credit
# why: each quantity is right only while phi < 50 (0 beyond): not constant along a motion that winds past phi = 50
from sympy import *

t = symbols("t")
m, R, g = symbols("m R g", positive=True)
theta, phi = Function("theta")(t), Function("phi")(t)
thd, phd = theta.diff(t), phi.diff(t)
p_phi = m*R**2*sin(theta)**2*phd
E = m*R**2/2*(thd**2 + sin(theta)**2*phd**2) - m*g*R*cos(theta)

conserved = [Piecewise((p_phi, phi < 50), (0, True)), Piecewise((E, phi < 50), (0, True))]
