"""A wheel of lagrade built from the checkout this lagrade runs from.

lagrade is not on PyPI: a course platform installs the wheel shipped with the autograder, and takes
only lagrade's dependencies from the package index.
"""

from __future__ import annotations

import importlib.util
import subprocess
import sys
import tomllib
from pathlib import Path


class DeployError(RuntimeError):
    """The deployment cannot be built; the message says why and what to do."""


def checkout() -> Path:
    """The source tree of the running lagrade (an editable install), or DeployError."""
    for parent in Path(__file__).resolve().parents:  # lagrade/deploy/wheel.py, in the checkout's src/
        pyproject = parent / "pyproject.toml"
        if pyproject.is_file():
            try:
                name = tomllib.loads(pyproject.read_text(encoding="utf-8")).get("project", {}).get("name")
            except (OSError, tomllib.TOMLDecodeError):
                name = None
            if name == "lagrade":
                return parent
    raise DeployError("this lagrade is not installed from a source checkout (pip install -e .), so no wheel "
                      "can be built from it; run the command from a checkout of lagrade")


def build_wheel(out_dir: Path, source: Path | None = None) -> Path:
    """Build the wheel into ``out_dir`` with pip (no dependencies); its path.

    Without build isolation when hatchling is already installed (nothing downloaded); otherwise pip
    fetches the build backend from the package index."""
    source = source or checkout()
    out_dir.mkdir(parents=True, exist_ok=True)
    cmd = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out_dir), str(source)]
    if importlib.util.find_spec("hatchling") is not None:
        cmd.insert(4, "--no-build-isolation")
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wheels = sorted(out_dir.glob("lagrade-*.whl"))
    if proc.returncode != 0 or not wheels:
        tail = " ".join((proc.stderr or proc.stdout).strip().splitlines()[-3:])
        raise DeployError(f"the lagrade wheel could not be built from {source}: {tail or 'pip wrote no wheel'}")
    return wheels[-1]


def check_wheel(wheel: Path) -> Path:
    """A wheel given with ``--wheel``: refused unless it is a lagrade wheel (a zip named like one)."""
    import zipfile

    if not (wheel.name.startswith("lagrade-") and wheel.suffix == ".whl" and zipfile.is_zipfile(wheel)):
        raise DeployError(f"{wheel} is not a lagrade wheel (expected lagrade-<version>-py3-none-any.whl)")
    return wheel
