"""Problem 12.41: Hamilton's canonical equations for (a) a projectile and (b) a simple pendulum.

(a) L = m(x'^2 + y'^2)/2 - m g y, p_x = m x', p_y = m y', H = (p_x^2 + p_y^2)/(2m) + m g y.
    x' = p_x/m, y' = p_y/m, p_x' = 0, p_y' = -m g  ->  p_x = m vx0, p_y = m vy0 - m g t,
    x = x0 + vx0 t, y = y0 + vy0 t - g t^2/2.
(b) L = m l^2 theta'^2/2 + m g l cos(theta), p_theta = m l^2 theta', H = p_theta^2/(2 m l^2) - m g l cos(theta).
    theta' = p_theta/(m l^2), p_theta' = -m g l sin(theta)  ->  theta'' = -(g/l) sin(theta);
    small amplitudes: theta'' = -(g/l) theta, from rest at theta0: theta = theta0 cos(sqrt(g/l) t).
    Exactly (motion_b, from rest at theta0 = 2 with l = 1, g = 9.81) the motion is Jacobi's
    sin(theta/2) = k sn(K(k^2) - sqrt(g/l) t | k^2), k = sin(theta0/2); here Hamilton's equations are
    integrated by classical Runge-Kutta (1000 steps per 0.1 s; an answer file imports sympy and math only).
"""
from sympy import Eq, Function, cos, sin, sqrt, symbols

t = symbols("t")
m, g, l = symbols("m g l", positive=True)
x0, y0, vx0, vy0, theta0 = symbols("x0 y0 vx0 vy0 theta0")

# (a)
x, y = Function("x")(t), Function("y")(t)
p_x, p_y = Function("p_x")(t), Function("p_y")(t)
H_a = (p_x**2 + p_y**2) / (2 * m) + m * g * y
hamilton_a = [
    Eq(x.diff(t), p_x / m),
    Eq(y.diff(t), p_y / m),
    Eq(p_x.diff(t), 0),
    Eq(p_y.diff(t), -m * g),
]
solution_a = {"x": x0 + vx0 * t, "y": y0 + vy0 * t - g * t**2 / 2}

# (b)
theta = Function("theta")(t)
p_theta = Function("p_theta")(t)
H_b = p_theta**2 / (2 * m * l**2) - m * g * l * cos(theta)
hamilton_b = [
    Eq(theta.diff(t), p_theta / (m * l**2)),
    Eq(p_theta.diff(t), -m * g * l * sin(theta)),
]
solution_b = {"theta": theta0 * cos(sqrt(g / l) * t)}

import math


def _rates(q, p):
    return p, -9.81 * math.sin(q)       # theta' = p/(m l^2), p' = -m g l sin(theta), m = l = 1


def _pendulum(q, p, h, steps):
    for _ in range(steps):
        k1 = _rates(q, p)
        k2 = _rates(q + h / 2 * k1[0], p + h / 2 * k1[1])
        k3 = _rates(q + h / 2 * k2[0], p + h / 2 * k2[1])
        k4 = _rates(q + h * k3[0], p + h * k3[1])
        q += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
        p += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    return q, p


_state, _table = (2.0, 0.0), [2.0]
for _ in range(40):
    _state = _pendulum(*_state, 1e-4, 1000)
    _table.append(_state[0])
motion_b = {"t": [i / 10 for i in range(41)], "theta": _table}
