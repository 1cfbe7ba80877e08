"""What a grader image installs, pinned: the base image by its exact tag, and every dependency of the
lagrade wheel (the whole closure) at the version installed where the image is built, in a
``requirements.txt`` shipped beside the wheel. An image built next month then runs the numpy, scipy
and sympy this build was tested with, not whatever PyPI holds that day (a new sympy can change how an
answer is read)."""

from __future__ import annotations

import re
from importlib import metadata

from lagrade.uses.deploy.wheel import DeployError

#: the PrairieLearn grader's base image: an exact Python release on an exact Debian release (a
#: floating tag such as ``python:3.11-slim`` moves under the image). To pin by digest as well, look it
#: up (``docker buildx imagetools inspect python:3.11.11-slim-bookworm``) and append ``@sha256:...``.
BASE_IMAGE = "python:3.11.11-slim-bookworm"
#: an exact tag (``python:3.11.11-slim-bookworm``), optionally with its digest
PINNED_IMAGE = re.compile(r"^[a-z0-9._/-]+:\d+\.\d+\.\d+[-.\w]*(@sha256:[0-9a-f]{64})?$")

#: the platform the grader images run on (PrairieLearn's linux/amd64; Gradescope's Ubuntu), for the
#: dependencies' environment markers (``pyseccomp; sys_platform == 'linux'``)
TARGET = {"implementation_name": "cpython", "platform_python_implementation": "CPython",
          "platform_system": "Linux", "sys_platform": "linux", "os_name": "posix", "platform_machine": "x86_64",
          "python_version": "3.11", "python_full_version": "3.11.11", "implementation_version": "3.11.11",
          "platform_release": "", "platform_version": ""}


def _packaging():
    try:
        from packaging.markers import default_environment  # noqa: F401
        from packaging.requirements import Requirement
        from packaging.utils import canonicalize_name
    except ImportError:  # pip carries its own copy
        from pip._vendor.packaging.requirements import Requirement  # type: ignore[no-redef]
        from pip._vendor.packaging.utils import canonicalize_name  # type: ignore[no-redef]
    return Requirement, canonicalize_name


def pinned_requirements(root: str = "lagrade") -> list[str]:
    """``name==version`` for every distribution ``root`` needs on the grader's platform (its
    requirements, theirs, and so on; extras only where a requirement asks for them), at the version
    installed here, sorted. DeployError naming a dependency that is not installed here (its version
    cannot be known): install it, then build again."""
    Requirement, canonicalize_name = _packaging()
    pins: dict[str, str] = {}
    todo: list[tuple[str, frozenset[str]]] = [(root, frozenset())]
    seen: set[tuple[str, frozenset[str]]] = set()
    while todo:
        name, extras = todo.pop()
        key = canonicalize_name(name)
        if (key, extras) in seen:
            continue
        seen.add((key, extras))
        try:
            dist = metadata.distribution(name)
        except metadata.PackageNotFoundError:
            raise DeployError(f"{name} (a dependency of {root} on the grader's platform) is not installed here, so "
                              f"its version cannot be pinned: pip install {name}, then build again") from None
        if key != canonicalize_name(root):
            pins[key] = f"{dist.metadata['Name']}=={dist.version}"
        for line in dist.requires or []:
            req = Requirement(line)
            if req.marker is not None and not any(req.marker.evaluate({**TARGET, "extra": e})
                                                  for e in (extras or {""})):
                continue
            todo.append((req.name, frozenset(req.extras)))
    return sorted(pins.values(), key=str.lower)


def requirements_txt(root: str = "lagrade") -> str:
    """The ``requirements.txt`` a grader image installs before the wheel, with a header that says why."""
    lines = pinned_requirements(root)
    return ("# lagrade's dependencies, pinned to the versions installed where this was built\n"
            "# (lagrade.uses.deploy.pins): the grader image installs exactly these.\n" + "\n".join(lines) + "\n")
