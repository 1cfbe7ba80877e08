"""lagrade: grades answers to Lagrangian and Hamiltonian dynamics problems."""

__version__ = "0.1.0"


def check(problem, answer=None, **kwargs):
    """Grade an answer file, or parts given as sympy objects: ``lagrade.check("12.43", H=...)``."""
    from lagrade.grade import check as _check

    return _check(problem, answer, **kwargs)


__all__ = ["check", "__version__"]
