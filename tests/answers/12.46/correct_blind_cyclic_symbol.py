from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X, p_theta = symbols("p_X p_theta")
L = (M + m)*dot(X)**2/2 + m*l*cos(theta)*dot(X)*dot(theta) + m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)
H = (m*l**2*p_X**2 - 2*m*l*cos(theta)*p_X*p_theta + (M + m)*p_theta**2)/(2*m*l**2*(M + m*sin(theta)**2)) - m*g*l*cos(theta)
cyclic = [Symbol("X")]
conserved = [L.diff(dot(X))]
omega = sqrt(g/l + m*g/(M*l))

# (b) X eliminated: the theta equation with X'' from the conserved p_X, unsolved
eom_reduced = Eq(l * (M + m * sin(theta) ** 2) * dot(theta, 2) + m * l * sin(theta) * cos(theta) * dot(theta) ** 2,
                 -(M + m) * g * sin(theta))
