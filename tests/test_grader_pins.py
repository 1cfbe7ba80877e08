"""The grader images pin what they install (issue 47): the PrairieLearn image's base by an exact
release tag, and every dependency of the lagrade wheel, the whole closure, at the version installed
here (requirements.txt beside the wheel, in the image's build context and in Gradescope's zip)."""

from __future__ import annotations

import re
from importlib import metadata

import pytest

from lagrade.uses.deploy import pins
from lagrade.uses.deploy.wheel import DeployError


def test_every_dependency_is_pinned_to_the_installed_version():
    lines = pins.pinned_requirements()
    assert lines and all(re.fullmatch(r"[A-Za-z0-9._-]+==[A-Za-z0-9.+!_-]+", x) for x in lines), lines
    got = {x.split("==")[0].lower().replace("_", "-"): x.split("==")[1] for x in lines}
    for name in ("numpy", "scipy", "sympy", "symengine", "pydantic", "click", "rich", "matplotlib",
                 "antlr4-python3-runtime", "python-flint"):
        assert got[name] == metadata.version(name), name  # lagrade's own requirements
    assert got["mpmath"] == metadata.version("mpmath")  # and theirs (sympy's)
    assert "pyseccomp" in got and "landlock" in got  # linux-only: the grader runs on Linux
    assert "lagrade" not in got and "pytest" not in got and "fastapi" not in got  # no extra of lagrade's


def test_a_dependency_not_installed_here_is_said(monkeypatch):
    real = metadata.distribution

    def missing(name):
        if name.lower() == "mpmath":
            raise metadata.PackageNotFoundError(name)
        return real(name)

    monkeypatch.setattr(pins.metadata, "distribution", missing)
    with pytest.raises(DeployError, match=r"mpmath .* is not installed here.*pip install mpmath"):
        pins.pinned_requirements()


@pytest.mark.parametrize("image, pinned", [
    (pins.BASE_IMAGE, True), ("python:3.11.11-slim-bookworm@sha256:" + "a" * 64, True),
    ("python:3.11-slim", False), ("python:latest", False), ("python:3-slim", False), ("python", False)])
def test_the_base_image_is_an_exact_release(image, pinned):
    assert bool(pins.PINNED_IMAGE.match(image)) is pinned


def test_the_requirements_file_says_why():
    text = pins.requirements_txt()
    assert text.startswith("# lagrade's dependencies, pinned") and text.endswith("\n")
    assert [x for x in text.splitlines() if not x.startswith("#")] == pins.pinned_requirements()
