# L plus a total derivative and a constant; H by inverting the mass matrix; momentum as total mass times centre-of-mass velocity.
from sympy import Function, Matrix, cos, sin, sqrt, symbols

t = symbols("t")
m, M, l, g = symbols("m M l g", positive=True)
X, theta = Function("X")(t), Function("theta")(t)
pX, pth = symbols("p_X p_theta")

L = (M + m) / 2 * X.diff(t) ** 2 + m * l * cos(theta) * X.diff(t) * theta.diff(t) \
    + m * l**2 / 2 * theta.diff(t) ** 2 + m * g * l * cos(theta) + (X * sin(theta)).diff(t) - m * g * l
A = Matrix([[M + m, m * l * cos(theta)], [m * l * cos(theta), m * l**2]])
p = Matrix([pX, pth])
H = (p.T * A.inv() * p)[0] / 2 - m * g * l * cos(theta)
cyclic = ["X"]
x_cm = (M * X + m * (X + l * sin(theta))) / (M + m)
conserved = [(M + m) * x_cm.diff(t)]
omega = sqrt((M + m) * g / (M * l))

# (b) X eliminated: the theta equation of the reduced Lagrangian, times 2 and as an expression meaning = 0
eom_reduced = 2 * (l * (M + m * sin(theta) ** 2) * theta.diff(t, 2) + m * l * sin(theta) * cos(theta) * theta.diff(t) ** 2
                   + (M + m) * g * sin(theta))
