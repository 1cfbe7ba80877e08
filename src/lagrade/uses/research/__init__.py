"""Research around the grader, never imported by it: symplectic integrators, finite-time Lyapunov
exponents, the work-precision sweep (``lagrade bench accuracy``) and the effects benchmark. An
import-linter contract keeps grading from depending on any of it."""
