"""The Gradescope autograder zip: ``setup.sh``, ``run_autograder``, the lagrade and problem-data
wheels, the assignment.

Gradescope unpacks the zip into ``/autograder/source``, runs ``setup.sh`` once as root when it
builds the image, copies ``run_autograder`` to ``/autograder/run_autograder`` and runs it for each
submission (files in ``/autograder/submission``), which must leave
``/autograder/results/results.json``.

Python: lagrade needs Python 3.11 (``tomllib`` in the problem, assignment and answer readers, and
3.11's typing and exception features elsewhere), and Gradescope's Ubuntu 22.04 base image has 3.10.
Lowering the minimum would mean a second TOML parser and a 3.10 test matrix for the whole engine, so
``setup.sh`` installs Python 3.11 instead: from Ubuntu's own archive (``python3.11`` is in 22.04's
universe), else from the deadsnakes PPA, unless a Python >= 3.11 is already there; lagrade goes into
a virtual environment at ``$AUTOGRADER_ROOT/venv`` from the shipped wheel, its dependencies from PyPI
at the exact versions of the shipped ``requirements.txt`` (:mod:`lagrade.uses.deploy.pins`), pip itself
at the version of the machine that built the zip. Gradescope's base image is chosen in its settings
(Ubuntu 22.04), not in the zip: setup.sh prints what it ran on.
"""

from __future__ import annotations

import shutil
import stat
import tempfile
import zipfile
from pathlib import Path

from lagrade.uses.deploy.wheel import DeployError, check_wheel, grader_wheels

SETUP_SH = r"""#!/usr/bin/env bash
# lagrade's Gradescope setup: run once, as root, when Gradescope builds the autograder image.
# lagrade needs Python >= 3.11; Gradescope's Ubuntu 22.04 image has 3.10, so 3.11 is installed.
set -euo pipefail
ROOT="${AUTOGRADER_ROOT:-/autograder}"
SRC="$ROOT/source"
PY="${LAGRADE_SETUP_PYTHON:-}"
grep -h '^PRETTY_NAME=' /etc/os-release 2>/dev/null || true   # the base image, in the build log
if [ -z "$PY" ]; then
  for c in python3.13 python3.12 python3.11 python3; do
    if command -v "$c" >/dev/null 2>&1 && "$c" -c 'import sys, venv; sys.exit(sys.version_info < (3, 11))' 2>/dev/null
    then PY="$(command -v "$c")"; break; fi
  done
fi
if [ -z "$PY" ]; then
  export DEBIAN_FRONTEND=noninteractive
  apt-get update
  if ! apt-get install -y python3.11 python3.11-venv; then
    apt-get install -y software-properties-common
    add-apt-repository -y ppa:deadsnakes/ppa
    apt-get update
    apt-get install -y python3.11 python3.11-venv
  fi
  PY=python3.11
fi
"$PY" -m venv "$ROOT/venv"
# every dependency at the version the autograder was built with (requirements.txt, exact pins), then
# the two wheels without resolving anything more: a rebuild next term installs the same packages
"$ROOT/venv/bin/python" -m pip install --quiet "pip==@PIP@"
"$ROOT/venv/bin/python" -m pip install -r "$SRC/requirements.txt"
"$ROOT/venv/bin/python" -m pip install --no-deps "$SRC"/lagrade-*.whl "$SRC"/lagrade_chapter12-*.whl
"$ROOT/venv/bin/python" -m pip check
# the reference cache of the assignment's problems, built once here rather than at the first submissions
EXTRA=()
if [ -d "$SRC/problems" ]; then EXTRA=(--problems "$SRC/problems"); fi
IDS="$("$ROOT/venv/bin/python" -c 'import sys; from lagrade.uses.bulk.assignment import load_assignment
print(" ".join(load_assignment(sys.argv[1]).ids))' "$SRC/assignment.toml")"
# shellcheck disable=SC2086
"$ROOT/venv/bin/python" -m lagrade cache build $IDS "${EXTRA[@]}" \
  || echo "lagrade: the reference cache was not built; grading builds it"
# the key for the grader's uid (root) only: answers run as another uid, and where the container gives
# no mount namespace and no Landlock that uid is what keeps them from the problem data, the references,
# the cache and the wheels here (lagrade gradescope run checks it before grading)
DATA="$("$ROOT/venv/bin/python" -c 'from lagrade.problem.library import data_root; print(data_root() or "")')"
CACHE="$("$ROOT/venv/bin/python" -c 'from lagrade.problem.library import cache_dir; print(cache_dir() or "")')"
for d in "$DATA" "$CACHE" "$SRC"; do
  if [ -n "$d" ] && [ -e "$d" ]; then chmod -R go-rwx "$d"; chmod 0700 "$d"; fi
done
"$ROOT/venv/bin/python" -m lagrade doctor || true   # what the sandbox can use on this image, in the build log
"""

RUN_AUTOGRADER = r"""#!/usr/bin/env bash
# lagrade's Gradescope autograder: run for each submission. AUTOGRADER_ROOT: another root (tests);
# LAGRADE_PYTHON: another Python with lagrade installed (default: the venv setup.sh made).
ROOT="${AUTOGRADER_ROOT:-/autograder}"
PY="${LAGRADE_PYTHON:-$ROOT/venv/bin/python}"
RESULTS="$ROOT/results/results.json"
mkdir -p "$ROOT/results"
rm -f "$RESULTS"
EXTRA=()
if [ -d "$ROOT/source/problems" ]; then EXTRA=(--problems "$ROOT/source/problems"); fi
cd "$ROOT" 2>/dev/null || true
"$PY" -m lagrade gradescope run --submission "$ROOT/submission" --assignment "$ROOT/source/assignment.toml" \
  --results "$RESULTS" "${EXTRA[@]}"
status=$?
if [ ! -s "$RESULTS" ]; then
  # lagrade itself failed: the student still gets a result that says so, never a silent zero
  printf '%s\n' "{\"score\": 0, \"output\": \"The autograder could not grade this submission (lagrade exited with status $status). Please tell your instructor; the grade will be fixed by hand.\", \"output_format\": \"text\", \"visibility\": \"visible\", \"stdout_visibility\": \"hidden\", \"tests\": []}" > "$RESULTS"
fi
exit 0
"""

def _add(z: zipfile.ZipFile, name: str, data: bytes, executable: bool = False) -> None:
    info = zipfile.ZipInfo(name, date_time=(2020, 1, 1, 0, 0, 0))
    info.compress_type = zipfile.ZIP_DEFLATED
    info.external_attr = (0o755 if executable else 0o644) << 16 | stat.S_IFREG << 16
    z.writestr(info, data)


def build_autograder(assignment_path: Path, output: Path, problems_dirs: tuple[Path, ...] = (),
                     wheel: Path | None = None) -> list[str]:
    """Write the autograder zip to ``output``; the names it holds.

    The assignment is shipped as ``assignment.toml``; extra problem folders go into ``problems/``
    (their ``*.toml``), which ``run_autograder`` passes on with ``--problems``. ``wheel``: an existing
    lagrade wheel to ship instead of building one (the problem data's wheel is taken from beside it,
    else built)."""
    from lagrade.uses.bulk.assignment import check_against_problems, load_assignment

    assignment = load_assignment(assignment_path)
    check_against_problems(assignment, problems_dirs)
    if wheel is not None:
        check_wheel(wheel)
    with tempfile.TemporaryDirectory(prefix="lagrade-gradescope-build-") as tmp:
        wheels = grader_wheels(Path(tmp) / "wheel", wheel)
        output.parent.mkdir(parents=True, exist_ok=True)
        part = output.with_name(output.name + ".part")
        with zipfile.ZipFile(part, "w") as z:
            from importlib.metadata import version

            from lagrade.uses.deploy.pins import requirements_txt

            _add(z, "setup.sh", SETUP_SH.replace("@PIP@", version("pip")).encode(), executable=True)
            _add(z, "requirements.txt", requirements_txt().encode())
            _add(z, "run_autograder", RUN_AUTOGRADER.encode(), executable=True)
            for whl in wheels:
                _add(z, whl.name, whl.read_bytes())
            _add(z, "assignment.toml", Path(assignment_path).read_bytes())
            for folder in problems_dirs:
                for f in sorted(Path(folder).glob("*.toml")):
                    _add(z, f"problems/{f.name}", f.read_bytes())
            names = z.namelist()
        part.replace(output)
    return names


def install_fake_root(zip_path: Path, root: Path) -> Path:
    """Lay out ``root`` as Gradescope does (``source/`` unpacked, ``run_autograder`` copied, an empty
    ``submission/``): for tests and for trying an autograder locally. The ``run_autograder`` path."""
    source = root / "source"
    with zipfile.ZipFile(zip_path) as z:
        for info in z.infolist():
            target = (source / info.filename).resolve()
            if not target.is_relative_to(source.resolve()):
                raise DeployError(f"{zip_path}: {info.filename} would land outside {source}")
            z.extract(info, source)
            mode = (info.external_attr >> 16) & 0o777
            if mode:
                target.chmod(mode)
    run = root / "run_autograder"
    shutil.copyfile(source / "run_autograder", run)
    run.chmod(0o755)
    (root / "submission").mkdir(exist_ok=True)
    return run
