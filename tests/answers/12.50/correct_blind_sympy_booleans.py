from lagrade.answer import *

m, k, tau = parameters("m k tau")
x = coordinates("x")
p_x = symbols("p_x")
V = k*exp(-t/tau)/x
L = m*dot(x)**2/2 - V
H = p_x**2/(2*m) + V
dH_dt = -k*exp(-t/tau)/(tau*x)
H_conserved = S.false             # sympy's booleans
H_is_E = Eq(H, p_x**2/(2*m) + V)  # evaluates to sympy's True
eom = [Eq(dot(x, 2), k*exp(-t/tau)/(m*x**2))]

# the solution as {time: value}, sympy numbers, 4 significant figures, uneven times
from sympy import Float, Rational
solution = {Rational(0): Float("1.0"), Rational(1, 4): Float("1.029"), 1: Float("1.336"), 2: Float("1.935"),
            3: Float("2.579"), Float("4.2"): Float("3.364")}
