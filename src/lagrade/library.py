"""Where problem files, reference solutions and the reference cache live, and finding a problem by
its id. The sandbox hides all three from answers, so their places are named here, below both.

Problems are data: the bundled ones ship inside the package (or sit in the source tree for an
editable install), and an instructor adds their own with ``--problems DIR`` or ``LAGRADE_PROBLEMS``
without touching the engine.
"""

from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path

from lagrade.spec import Problem, SpecError, load_problem_file

_PACKAGE = Path(__file__).resolve().parent


def _bundled(name: str) -> Path:
    packaged = _PACKAGE / "_data" / name
    return packaged if packaged.is_dir() else _PACKAGE.parents[1] / name


def problem_dirs(extra: tuple[Path, ...] = ()) -> list[Path]:
    env = [Path(p) for p in os.environ.get("LAGRADE_PROBLEMS", "").split(os.pathsep) if p]
    return [*extra, *env, _bundled("problems")]


def reference_dir() -> Path:
    return _bundled("reference_solutions")


CACHE_ENV = "LAGRADE_CACHE"


def cache_dir() -> Path | None:
    """Where the reference cache's entries live (:mod:`lagrade.cache`), or None when caching is off."""
    setting = os.environ.get(CACHE_ENV, "")
    if setting.lower() in ("off", "0", "no", "false"):
        return None
    if setting:
        return Path(setting).expanduser()
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "lagrade"


def _sort_key(pid: str) -> tuple:
    """The chapter's problems, then its exercises and examples, then any other course's ids; each
    in natural order (12.2 before 12.10, hw7-q2 before hw7-q10)."""
    group = next((i for i, prefix in enumerate(("12.", "ex12.", "eg12.")) if pid.startswith(prefix)), 3)
    return group, [(0, int(chunk), "") if chunk.isdigit() else (1, 0, chunk) for chunk in re.findall(r"\d+|\D+", pid)]


@lru_cache(maxsize=8)
def _index(dirs: tuple[Path, ...]) -> dict[str, Path]:
    found: dict[str, Path] = {}
    for d in dirs:
        if not d.is_dir():
            continue
        for f in sorted(d.glob("*.toml")):
            found.setdefault(f.stem, f)
    return dict(sorted(found.items(), key=lambda kv: _sort_key(kv[0])))


def problem_ids(extra: tuple[Path, ...] = ()) -> list[str]:
    return list(_index(tuple(problem_dirs(extra))))


def problem_path(pid: str, extra: tuple[Path, ...] = ()) -> Path:
    index = _index(tuple(problem_dirs(extra)))
    if pid not in index:
        known = ", ".join(list(index)[:12])
        raise SpecError(f"no problem '{pid}' (known ids: {known}{', ...' if len(index) > 12 else ''})")
    return index[pid]


@lru_cache(maxsize=128)
def _load(path: Path, mtime: float) -> Problem:  # noqa: ARG001 (mtime keys the cache)
    problem = load_problem_file(path)
    if problem.id != path.stem:
        raise SpecError(f"{path}: the file declares id '{problem.id}' but is named '{path.stem}.toml'")
    return problem


def load_problem(pid_or_path: str | Path, extra: tuple[Path, ...] = ()) -> Problem:
    """A problem by id (``12.22``) or by the path of its file."""
    path = Path(pid_or_path)
    if not (path.suffix == ".toml" and path.exists()):
        path = problem_path(str(pid_or_path), extra)
    return _load(path.resolve(), path.stat().st_mtime)
