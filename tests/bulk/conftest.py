"""Fixtures for the bulk-grading tests: generated classes and a checker of expected scores."""

from __future__ import annotations

import pytest


@pytest.fixture
def sentinel(tmp_path):
    path = tmp_path / "outside" / "pwned"
    path.parent.mkdir()
    yield str(path)
    assert not path.exists(), "a submission wrote outside the sandbox"
