from lagrade.answer import *

M, R, g = symbols("M R g", positive=True)
theta = Symbol("theta", positive=True)
s = Function("s", real=True)(t)
L = M*Derivative(s, t)**2/2 + Rational(1, 5)*M*R**2*(Derivative(s, t)/R)**2 + M*g*s*sin(theta)
a = 5*g*sin(theta)/7
