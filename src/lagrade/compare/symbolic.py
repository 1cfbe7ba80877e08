"""Time-bounded symbolic proof that an expression is zero.

sympy's simplification can run for minutes on expressions a student writes in a few seconds
(the double pendulum is the classic case), so each attempt runs under a wall-clock bound and
"gave up" is a normal outcome: the numeric and trajectory evidence then decide.
"""

from __future__ import annotations

import signal
import sys
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
    CPU bound, turning a slow proof into a wrong 'took too long' verdict.

    A raise that lands in a gc callback or a ``__del__`` is dropped by Python and handed to
    ``sys.unraisablehook``; as in ``verdicts.grade.cpu_time_bound`` it is kept from the hook (pytest's
    formats it, longer than the 0.05 s between alarms, and an alarm inside the hook failed a test:
    issue 45) and raised again at the next call of Python code."""
    if seconds <= 0:
        raise _OutOfTime
    if threading.current_thread() is not threading.main_thread() or not hasattr(signal, "setitimer"):
        yield
        return

    leaving = []
    hook, profiler = sys.unraisablehook, sys.getprofile()

    def _alarm(signum, frame):  # noqa: ARG001
        if not leaving:
            raise _OutOfTime

    def _raise_at_next_call(frame, event, arg) -> None:  # noqa: ARG001
        if frame.f_code is _dropped.__code__:  # the hook's own return
            return
        sys.setprofile(profiler)
        if not leaving:
            raise _OutOfTime

    def _dropped(unraisable) -> None:
        if not isinstance(unraisable.exc_value, _OutOfTime):
            hook(unraisable)
        elif not leaving:
            sys.setprofile(_raise_at_next_call)

    previous = signal.signal(signal.SIGALRM, _alarm)
    sys.unraisablehook = _dropped
    signal.setitimer(signal.ITIMER_REAL, seconds, 0.05)
    try:
        yield
    finally:
        leaving.append(True)
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        if sys.unraisablehook is _dropped:
            sys.unraisablehook = hook
        if sys.getprofile() is _raise_at_next_call:
            sys.setprofile(profiler)


def _positive(expr: sp.Expr, positive: set[str]) -> sp.Expr:
    mapping = {s: sp.Symbol(s.name, positive=True) for s in expr.free_symbols
               if isinstance(s, sp.Symbol) and s.name in positive}
    return expr.xreplace(mapping)


STEPS: list[tuple[str, Callable[[sp.Expr], sp.Expr]]] = [
    ("cancel", lambda e: sp.cancel(sp.together(e))),
    ("expand", lambda e: sp.expand(e)),
    ("denest", lambda e: sp.expand(sp.sqrtdenest(sp.expand(e)))),  # sqrt(3 + 2*sqrt(2)) is 1 + sqrt(2)
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
    if any(x.base.is_zero and not x.exp.is_number for x in expr.atoms(sp.Pow)):
        return None  # 0**u is 0 for u > 0 and infinite for u < 0, and sympy's simplification takes it as 0
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
