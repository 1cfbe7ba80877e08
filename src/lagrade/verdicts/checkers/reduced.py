"""Eliminating a cyclic coordinate (Routh): the reduced equation of motion, or the Routhian itself.

The book asks to "eliminate this coordinate": a student may answer with the equation(s) left for the
other coordinates or with the Routhian R(q, q', p_cyclic). Both are graded against one reduced scene
(the part's ``system``, whose parameters include the constant momenta): equations by their
accelerations, R by its Euler-Lagrange equations. R's sign is a convention (R = L - p q' in some
books, p q' - L in others) that does not change its equations, so either sign is right.
"""

from __future__ import annotations

import sympy as sp

from lagrade.verdicts.checkers.base import Context, InvalidAnswer, as_expr, graded
from lagrade.verdicts.checkers.dynamics import check_eom, check_lagrangian
from lagrade.verdicts.result import PartResult
from lagrade.problem.spec import Part


def _is_equation(value: object) -> bool:
    """Equations (Eq, lists, dicts, or an expression with accelerations meaning = 0) versus a Routhian."""
    if isinstance(value, (list, tuple, dict, sp.Equality, sp.MatrixBase)):
        return True
    if isinstance(value, sp.Basic):
        if any(d.derivative_count >= 2 for d in value.atoms(sp.Derivative)):
            return True
        return any(s.name.endswith("_dd") for s in value.free_symbols if isinstance(s, sp.Symbol))
    return False


def check_reduced(ctx: Context, part: Part, value: object) -> PartResult:
    if _is_equation(value):
        return check_eom(ctx, part, value)
    routhian = as_expr(value, part)
    if routhian.is_number:
        raise InvalidAnswer(f"{part.name} should be the reduced equation(s) of motion, or the Routhian as an "
                            f"expression in the remaining coordinates, their velocities and the constant momenta")
    first = check_lagrangian(ctx, part, routhian)
    if first.verdict == "correct":
        return graded(part, 1.0, first.method, "correct: a Routhian of the reduced motion (R = L - p*q' of the "
                                               "cyclic coordinate).")
    flipped = check_lagrangian(ctx, part, -routhian)
    if flipped.verdict == "correct":
        return graded(part, 1.0, flipped.method, "correct: a Routhian of the reduced motion (R = p*q' - L of the "
                                                 "cyclic coordinate).")
    return first
