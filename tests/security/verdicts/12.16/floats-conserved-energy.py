# target: conserved
# family: floats
# expect: no-credit
# why: the potential term carries 1.000000001: this energy changes along the motion by about 1e-9
from sympy import *

t = symbols("t")
m, R, g = symbols("m R g", positive=True)
theta, phi = Function("theta")(t), Function("phi")(t)
thd, phd = theta.diff(t), phi.diff(t)
p_phi = m*R**2*sin(theta)**2*phd
E = m*R**2/2*(thd**2 + sin(theta)**2*phd**2) - m*g*R*cos(theta)

conserved = [m*R**2/2*(thd**2 + sin(theta)**2*phd**2) - Float("1.000000001")*m*g*R*cos(theta)]
