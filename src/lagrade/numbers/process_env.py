"""The environment lagrade's own processes start with (the ``lagrade`` script and its graders)."""

from __future__ import annotations

from collections.abc import MutableMapping


def single_threaded_blas(env: MutableMapping[str, str]) -> None:
    """One OpenBLAS thread, unless the user chose otherwise; it must be set before numpy is imported.

    lagrade's linear algebra is on matrices of a few rows, which OpenBLAS never splits across
    threads, while starting its pools (numpy and scipy each bundle one) cost 0.1-0.24 s of CPU per
    process (`import numpy, scipy.integrate`, 12 alternated runs): a class pays it in every grader,
    on the cores that grade."""
    env.setdefault("OPENBLAS_NUM_THREADS", "1")
