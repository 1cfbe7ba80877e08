from lagrade.answer import *

m, M, l, g = parameters("m M l g")
X, theta = coordinates("X theta")
p_X, p_theta = momenta("p_X p_theta")
xb, yb = X + l*sin(theta), -l*cos(theta)
L = M*dot(X)**2/2 + m*(xb.diff(t)**2 + yb.diff(t)**2)/2 - m*g*yb
Mm = Matrix([[M + m, m*l*cos(theta)], [m*l*cos(theta), m*l**2]])
p = Matrix([p_X, p_theta])
H = (p.T*Mm.inv()*p)[0]/2 - m*g*l*cos(theta)
cyclic = [X]
conserved = [L.diff(dot(X))]
omega = sqrt(g/(l*M/(M + m)))

# (b) X eliminated: Routhian R = L - p_X*X' with X' = (p_X - m*l*cos(theta)*theta')/(M + m)
_Xd = (p_X - m * l * cos(theta) * dot(theta)) / (M + m)
routhian = ((M + m) / 2 * _Xd**2 + m * l * cos(theta) * _Xd * dot(theta) + m * l**2 / 2 * dot(theta) ** 2
            + m * g * l * cos(theta) - p_X * _Xd)
