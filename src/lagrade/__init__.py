"""lagrade: grades answers to Lagrangian and Hamiltonian dynamics problems.

The public API: :func:`check`, :func:`load_problem`, :class:`CheckResult`, :class:`Problem`. They
are loaded on first use, because every sandbox child imports this package (``lagrade.answer``) and
must not pay for, or hold, the grader.
"""

from lagrade._version import __version__

__all__ = ["CheckResult", "Problem", "__version__", "check", "load_problem"]

_LAZY = {"CheckResult": "lagrade.verdicts.result", "Problem": "lagrade.problem.spec", "load_problem": "lagrade.problem.library"}


#: options of a local check; the course server decides them itself
_LOCAL_OPTIONS = {"problem_dirs", "accuracy", "only", "hints", "credit", "read_as", "grading_seconds", "limits",
                  "meanwhile"}


def check(problem, answer=None, *, server=None, token=None, plot=True, **kwargs):
    """Grade an answer file (``.py``, ``.toml``, ``.ipynb``), or parts given as sympy objects:
    ``lagrade.check("12.43", H=...)``. A part given as None is not answered yet (the template
    notebook's placeholder). ``server``, ``token``: the course server grades it, at the course's
    feedback level (docs/server.md); nothing of the problem is needed here. In Jupyter the result
    shows the verdicts, the answer as read, the feedback and, with ``plot``, the picture of a wrong
    motion (drawn when first shown)."""
    parts = {name: value for name, value in kwargs.items() if value is not None}
    if server is not None:
        local = sorted(set(parts) & _LOCAL_OPTIONS)
        if local:  # the server grades as its assignment says
            raise TypeError(f"{', '.join(local)}: not with server= (the course server decides how it grades)")
        from lagrade.uses.server.client import check_remote

        return check_remote(server, token, str(problem), answer, parts, plot=plot)
    from lagrade.verdicts.grade import check as _check

    result = _check(problem, answer, **parts)
    if plot:
        from lagrade.verdicts.plot import plot_png

        result._picture = lambda: plot_png(result)
    return result


def __getattr__(name: str):
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'lagrade' has no attribute {name!r}")
