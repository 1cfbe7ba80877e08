"""Problem 12.15: the double pendulum of 12.14 in the limits m1 >> m2 and m1 << m2.

Small oscillations (12.14): (m1 + m2) l1 th1'' + m2 l2 th2'' = -(m1 + m2) g th1,
                            l1 th1'' + l2 th2'' = -g th2.
With th ~ exp(i w t), W = w**2:  m1 l1 l2 W**2 - (m1 + m2)(l1 + l2) g W + (m1 + m2) g**2 = 0.

(a) m2/m1 -> 0: divide by m1: l1 l2 W**2 - (l1 + l2) g W + g**2 = (l1 W - g)(l2 W - g) = 0,
    so W -> g/l1 and g/l2: the upper pendulum swings undisturbed, the lower one is driven by it.
    For l1 = l2 = l: W = (g/l)(1 + eps +- sqrt(eps (1 + eps))), eps = m2/m1: nearly degenerate -> beats.
(b) m1/m2 -> 0: the W**2 term drops for the slow root: W -> g/(l1 + l2) (one pendulum of length l1 + l2);
    the product of the roots is (m1 + m2) g**2/(m1 l1 l2) -> oo, so the fast root W ~ m2 g (l1 + l2)/(m1 l1 l2).
"""
from sympy import solve, sqrt, symbols

m1, m2, l1, l2, g, W = symbols("m1 m2 l1 l2 g W", positive=True)

roots = solve(m1 * l1 * l2 * W**2 - (m1 + m2) * (l1 + l2) * g * W + (m1 + m2) * g**2, W)
omega = [sqrt(r) for r in roots]

omega_a = [sqrt(g / l1), sqrt(g / l2)]
beats_a = True

omega_b = sqrt(g / (l1 + l2))
fast_mode_diverges_b = True
