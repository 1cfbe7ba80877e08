# expect: solution=incorrect
# Euler's method with step 0.5: the numbers are far from the motion after a few steps.
import math

x, v, t, h = 1.0, 0.0, 0.0, 0.5
times, xs = [0.0], [1.0]
for i in range(10):
    x, v = x + h * v, v + h * math.exp(-t) / x**2
    t += h
    times.append(t)
    xs.append(x)
solution = {"t": times, "x": xs}
