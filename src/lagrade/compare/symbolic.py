"""Time-bounded symbolic proof that an expression is zero.

sympy's simplification can run for minutes on expressions a student writes in a few seconds
(the double pendulum is the classic case), so each attempt runs under a wall-clock bound and
"gave up" is a normal outcome: the numeric and trajectory evidence then decide.
"""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager

import sympy as sp


class _OutOfTime(Exception):
    pass


@contextmanager
def time_bound(seconds: float) -> Iterator[None]:
    """Interrupt the enclosed pure-Python work after ``seconds`` (main thread only; else unbounded).
    The alarm repeats every 0.05 s until the block is left: sympy's own ``except Exception`` (or a
    gc callback) may swallow one raise, and a proof that ran on would then meet only the grading's
    CPU bound, turning a slow proof into a wrong 'took too long' verdict."""
    if seconds <= 0:
        raise _OutOfTime
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        yield
        return

    leaving = []

    def _alarm(signum, frame):  # noqa: ARG001
        if not leaving:
            raise _OutOfTime

    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, seconds, 0.05)
    try:
        yield
    finally:
        leaving.append(True)
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _positive(expr: sp.Expr, positive: set[str]) -> sp.Expr:
    mapping = {s: sp.Symbol(s.name, positive=True) for s in expr.free_symbols
               if isinstance(s, sp.Symbol) and s.name in positive}
    return expr.xreplace(mapping)


STEPS: list[tuple[str, Callable[[sp.Expr], sp.Expr]]] = [
    ("cancel", lambda e: sp.cancel(sp.together(e))),
    ("expand", lambda e: sp.expand(e)),
    ("trig", lambda e: sp.cancel(sp.expand_trig(sp.expand(e)))),
    ("trigsimp", lambda e: sp.trigsimp(sp.cancel(sp.together(e)))),
    ("simplify", lambda e: sp.simplify(e)),
]


def proves_zero(expr: sp.Expr, seconds: float = 2.0, positive: set[str] = frozenset()) -> bool | None:
    """True when a simplification reaches 0 in time; None when every attempt gave up or ran out."""
    deadline = time.monotonic() + seconds
    try:
        expr = _positive(sp.sympify(expr), set(positive))
    except Exception:
        return None
    if expr == 0:
        return True
    for _name, step in STEPS:
        remaining = deadline - time.monotonic()
        if remaining <= 0:
            return None
        try:
            with time_bound(remaining):
                if step(expr) == 0:
                    return True
        except _OutOfTime:
            return None
        except Exception:  # sympy can raise on odd input; that is "no proof", not a verdict
            continue
    return None


def proves_all_zero(exprs: list[sp.Expr], seconds: float = 3.0, positive: set[str] = frozenset()) -> bool | None:
    """Every expression proved zero within one shared time budget."""
    deadline = time.monotonic() + seconds
    for e in exprs:
        left = deadline - time.monotonic()
        if left <= 0 or proves_zero(e, left, positive) is not True:
            return None
    return True
