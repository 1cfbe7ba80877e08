"""The wheels a grader installs, built from the checkout this lagrade runs from: lagrade (the engine,
which holds no problem and no reference) and lagrade-chapter12 (the problems and reference solutions,
``chapter12/`` in the checkout).

lagrade is not on PyPI: a course platform installs the wheels shipped with the autograder, and takes
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
    for parent in Path(__file__).resolve().parents:  # lagrade/uses/deploy/wheel.py, in the checkout's src/
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


#: the folder of the checkout that builds the problem-data distribution, and its wheels' names
DATA_FOLDER = "chapter12"
DATA_WHEEL = "lagrade_chapter12-*.whl"


def _pip_wheel(source: Path, out_dir: Path, pattern: str, what: str) -> Path:
    """Build one wheel into ``out_dir`` with pip (no dependencies); its path.

    Without build isolation when hatchling is already installed (nothing downloaded); otherwise pip
    fetches the build backend from the package index."""
    out_dir.mkdir(parents=True, exist_ok=True)
    cmd = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet", "--wheel-dir", str(out_dir), str(source)]
    if importlib.util.find_spec("hatchling") is not None:
        cmd.insert(4, "--no-build-isolation")
    proc = subprocess.run(cmd, capture_output=True, text=True)
    wheels = sorted(out_dir.glob(pattern))
    if proc.returncode != 0 or not wheels:
        tail = " ".join((proc.stderr or proc.stdout).strip().splitlines()[-3:])
        raise DeployError(f"the {what} wheel could not be built from {source}: {tail or 'pip wrote no wheel'}")
    return wheels[-1]


def build_wheel(out_dir: Path, source: Path | None = None) -> Path:
    """The lagrade wheel (the engine alone), built into ``out_dir``; its path."""
    return _pip_wheel(source or checkout(), out_dir, "lagrade-*.whl", "lagrade")


def build_data_wheel(out_dir: Path, source: Path | None = None) -> Path:
    """The lagrade-chapter12 wheel (problems and reference solutions), built into ``out_dir``; its path."""
    folder = (source or checkout()) / DATA_FOLDER
    if not (folder / "pyproject.toml").is_file():
        raise DeployError(f"{folder} holds no pyproject.toml: the problem data cannot be packaged from this checkout")
    return _pip_wheel(folder, out_dir, DATA_WHEEL, "lagrade-chapter12")


def grader_wheels(out_dir: Path, wheel: Path | None = None) -> list[Path]:
    """What a grader installs: the lagrade wheel (``wheel``, given with ``--wheel``, or built) and
    the problem data's (a ``lagrade_chapter12-*.whl`` next to ``wheel``, else built from the checkout)."""
    if wheel is None:
        return [build_wheel(out_dir), build_data_wheel(out_dir)]
    check_wheel(wheel)
    beside = sorted(wheel.parent.glob(DATA_WHEEL))
    if beside:
        return [wheel, beside[-1]]
    try:
        return [wheel, build_data_wheel(out_dir)]
    except DeployError as exc:
        raise DeployError(f"{wheel} holds no problem data and none can be built ({exc}); put the "
                          f"lagrade_chapter12-<version>-py3-none-any.whl next to it") from None


def check_wheel(wheel: Path) -> Path:
    """A wheel given with ``--wheel``: refused unless it is a lagrade wheel (a zip named like one)."""
    import zipfile

    if not (wheel.name.startswith("lagrade-") and wheel.suffix == ".whl" and zipfile.is_zipfile(wheel)):
        raise DeployError(f"{wheel} is not a lagrade wheel (expected lagrade-<version>-py3-none-any.whl)")
    return wheel
