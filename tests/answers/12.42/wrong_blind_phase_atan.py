# expect: H=correct, hamilton=correct, solution=incorrect, omega=correct
from lagrade.answer import *

m, k = parameters("m k")
x0, v0 = symbols("x0 v0")
x = coordinates("x")
p_x = momenta("p_x")
H = p_x**2/(2*m) + k*x**2/2
hamilton = [Eq(dot(x), p_x/m), Eq(p_x.diff(t), -k*x)]
omega = sqrt(k/m)
# amplitude-phase form with atan instead of atan2: right only when x0 > 0
solution = {x: sqrt(x0**2 + v0**2/omega**2)*cos(omega*t - atan(v0/(omega*x0)))}
