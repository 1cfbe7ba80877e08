"""The stability suite's session check: the integrator keeps its order and its step control.

A lost order or a step that never shrinks makes every long integration of the suite tens of times
dearer (or endless) instead of wrong; the check below (`method_check`, milliseconds) runs once before
the suite's first test, and if it fails every test of the suite errors at once with its message, so
the suite fails in seconds rather than hanging (issue 34, item 4c).
"""

from __future__ import annotations

import pytest

from .method_check import check_the_method


@pytest.fixture(scope="session", autouse=True)
def _the_integrator_keeps_its_order():
    problems = check_the_method()
    if problems:
        pytest.fail("the integrator is broken, so the stability suite is not run:\n" + "\n".join(problems),
                    pytrace=False)
