"""Problem 12.7: the spring pendulum in polar coordinates (r, theta)."""
from sympy import Eq, Function, cos, oo, sin, sqrt, symbols

t = symbols("t")
m, k, l0, g = symbols("m k l0 g", positive=True)
r, theta = Function("r")(t), Function("theta")(t)
rd, thd = r.diff(t), theta.diff(t)

L = m / 2 * (rd**2 + r**2 * thd**2) + m * g * r * cos(theta) - k / 2 * (r - l0) ** 2
eom = [
    Eq(m * r.diff(t, 2), m * r * thd**2 + m * g * cos(theta) - k * (r - l0)),
    Eq(m * r**2 * theta.diff(t, 2) + 2 * m * r * rd * thd, -m * g * r * sin(theta)),
]
# (b) with theta = 0 the radial equation is m r'' = m g - k (r - l0): SHM about l0 + m g/k
omega = sqrt(k / m)
# (a) Simple pendulum of length l0: the spring must not stretch, k -> oo (r'' = -(k/m)(r - l0) + ... pins r at l0 on a
# time scale sqrt(m/k) far shorter than the swing's sqrt(l0/g)); then m l0^2 theta'' = -m g l0 sin(theta).
pendulum = {k: oo}
# (b) theta = 0 for all time is a motion (the theta equation holds: sin(0) = 0, theta' = 0); the r equation is then
# m r'' = m g - k (r - l0), linear with a restoring force: a harmonic oscillator about r = l0 + m g/k.
oscillator = {theta: 0}
