"""lagrade: grades answers to Lagrangian and Hamiltonian dynamics problems.

The public API: :func:`check`, :func:`load_problem`, :class:`CheckResult`, :class:`Problem`. They
are loaded on first use, because every sandbox child imports this package (``lagrade.answer``) and
must not pay for, or hold, the grader.
"""

from lagrade._version import __version__

__all__ = ["CheckResult", "Problem", "__version__", "check", "load_problem"]

_LAZY = {"CheckResult": "lagrade.verdicts.result", "Problem": "lagrade.problem.spec", "load_problem": "lagrade.problem.library"}


def check(problem, answer=None, **kwargs):
    """Grade an answer file, or parts given as sympy objects: ``lagrade.check("12.43", H=...)``."""
    from lagrade.verdicts.grade import check as _check

    return _check(problem, answer, **kwargs)


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'lagrade' has no attribute {name!r}")
