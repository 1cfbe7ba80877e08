# expect: solution=incorrect
# The table of x'' = k/(m x^2) with the factor exp(-t/tau) dropped: the repulsion does not fade, x runs away faster.
solution = {"t": [0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0],
            "x": [1.0, 1.1202, 1.4377, 1.8788, 2.3925, 2.951, 3.5386, 4.1465, 4.7691, 5.4028, 6.0451]}
