from lagrade.answer import *

m1, m2, l1, l2, g = parameters("m1 m2 l1 l2 g")
theta1, theta2 = coordinates("theta1 theta2")
x1, y1 = l1*sin(theta1), -l1*cos(theta1)
x2, y2 = x1 + l2*sin(theta2), y1 - l2*cos(theta2)
T = m1*(x1.diff(t)**2 + y1.diff(t)**2)/2 + m2*(x2.diff(t)**2 + y2.diff(t)**2)/2
V = g*(m1*y1 + m2*y2)
L = T - V
# linearized: solved for the accelerations
eom = [Eq(dot(theta1, 2), (-(m1 + m2)*g*theta1 + m2*g*theta2)/(m1*l1)),
       Eq(dot(theta2, 2), ((m1 + m2)*g*theta1 - (m1 + m2)*g*theta2)/(m1*l2))]
eom_exact = [L.diff(dot(q)).diff(t) - L.diff(q) for q in (theta1, theta2)]
mu = m2/m1
omega = [sqrt(g*(1 + mu)*(l1 + l2 + sqrt((l1 + l2)**2 - 4*l1*l2/(1 + mu)))/(2*l1*l2)),
         sqrt(g*(1 + mu)*(l1 + l2 - sqrt((l1 + l2)**2 - 4*l1*l2/(1 + mu)))/(2*l1*l2))]
