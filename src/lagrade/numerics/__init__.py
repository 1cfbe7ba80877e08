"""Numerics beyond the grader's comparison: scene models from declared effects, events, symplectic
integrators, finite-time Lyapunov exponents and the work-precision sweep (``lagrade bench accuracy``)."""
