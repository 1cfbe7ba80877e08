"""Problem 12.46: pendulum from a car on a frictionless rail."""
from sympy import Function, Matrix, cos, sqrt, symbols, simplify

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
Xd, thd = X.diff(t), theta.diff(t)
p_X, p_theta, th = symbols("p_X p_theta theta")

L = (M + m) / 2 * Xd**2 + m * l * cos(theta) * Xd * thd + m * l**2 / 2 * thd**2 + m * g * l * cos(theta)

# p = A qdot with the mass matrix A; H = p A^-1 p / 2 + V
A = Matrix([[M + m, m * l * cos(th)], [m * l * cos(th), m * l**2]])
p = Matrix([p_X, p_theta])
H = simplify((p.T * A.inv() * p)[0] / 2) - m * g * l * cos(th)

cyclic = ["X"]
conserved = [(M + m) * Xd + m * l * cos(theta) * thd]
omega = sqrt((M + m) * g / (M * l))
