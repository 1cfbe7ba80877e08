"""Test-session settings shared by every test path (tests/, problems/, reference_solutions/)."""

from __future__ import annotations

import os
import shutil
import tempfile

_CACHE: str | None = None


def pytest_configure(config):
    """A private disk cache per session (inherited by the CLI subprocesses the tests start): the suite
    never reads a developer's cache, and exercises both cold and warm checks as it goes."""
    global _CACHE
    if "LAGRADE_CACHE" not in os.environ:
        _CACHE = tempfile.mkdtemp(prefix="lagrade-test-cache-")
        os.environ["LAGRADE_CACHE"] = _CACHE


def pytest_unconfigure(config):
    if _CACHE is not None:
        os.environ.pop("LAGRADE_CACHE", None)
        shutil.rmtree(_CACHE, ignore_errors=True)
