from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X, p_theta = symbols("p_X p_theta")
L = (M + m)*dot(X)**2/2 + m*l*cos(theta)*dot(X)*dot(theta) + m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)
D = m*l**2*(M + m*sin(theta)**2)
H = (m*l**2*p_X**2 - 2*m*l*cos(theta)*p_X*p_theta + (M + m)*p_theta**2)/(2*D) - m*g*l*cos(theta)
cyclic = ["X"]
conserved = [(M + m)*dot(X) + m*l*cos(theta)*dot(theta)]
omega = sqrt((M + m)*g/(M*l))

# (b) X eliminated (Routh, R = p_X*X' - L): the p_X-free part, the p_X terms being a constant and a total derivative
eom_reduced = -m * l**2 * (M + m * sin(theta) ** 2) / (2 * (M + m)) * dot(theta) ** 2 - m * g * l * cos(theta)
