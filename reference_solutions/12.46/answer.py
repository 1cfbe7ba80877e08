"""Problem 12.46: pendulum from a car on a frictionless rail."""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
Xd, thd = X.diff(t), theta.diff(t)
p_X, p_theta, th = symbols("p_X p_theta theta")

L = (M + m) / 2 * Xd**2 + m * l * cos(theta) * Xd * thd + m * l**2 / 2 * thd**2 + m * g * l * cos(theta)

# p = A qdot with A = [[M + m, m l cos], [m l cos, m l^2]], det A = m l^2 (M + m sin^2);
# H = p.A^-1.p / 2 + V
H = (m * l**2 * p_X**2 - 2 * m * l * cos(th) * p_X * p_theta + (M + m) * p_theta**2) / (
    2 * m * l**2 * (M + m * sin(th)**2)) - m * g * l * cos(th)

cyclic = ["X"]
conserved = [(M + m) * Xd + m * l * cos(theta) * thd]
omega = sqrt((M + m) * g / (M * l))

# (b) X is cyclic: p_X = (M + m) X' + m l cos(theta) theta' is constant. Routh: X' = (p_X - m l cos theta theta')/(M + m)
# in R = L - p_X X' gives m l^2 (M + m sin^2 theta) theta'^2 / (2 (M + m)) + m g l cos(theta), plus a constant and
# d/dt(p_X m l sin(theta)/(M + m)); its Lagrange equation does not contain p_X:
eom_reduced = Eq(l * (M + m * sin(theta)**2) * theta.diff(t, 2) + m * l * sin(theta) * cos(theta) * thd**2,
                 -(M + m) * g * sin(theta))
