# expect: eom_xy=incorrect, eom=incorrect
# Multipliers kept, but the constraint force drawn along the wire (cos instead of sin) and the
# centrifugal term with the wrong sign: wrong once the multipliers are eliminated.
from sympy import Derivative, Eq, Function, cos, sin, symbols

t = symbols("t")
m, omega = symbols("m omega", positive=True)
x, y = Function("x")(t), Function("y")(t)
lam = symbols("lam")
eom_xy = [Eq(m * x.diff(t, 2), lam * cos(omega * t)),
          Eq(m * y.diff(t, 2), lam * sin(omega * t)),
          Eq(x * sin(omega * t) - y * cos(omega * t), 0)]
r, theta = Function("r")(t), Function("theta")(t)
eom = [m * r.diff(t, 2) + m * r * theta.diff(t) ** 2,
       Eq(Derivative(m * r**2 * theta.diff(t), t), lam),
       Eq(theta, omega * t)]
