"""Where problem files, reference solutions and the reference cache live, and finding a problem by
its id. The sandbox hides all three from answers, so their places are named here, below both.

Problems are data: the chapter's ship apart from the engine, in the ``lagrade-chapter12``
distribution (``chapter12/`` in the checkout), so that the ``lagrade`` wheel a student installs to
check against a course server holds no problem and no reference. An editable install reads the
checkout's folders in place; an instructor adds their own with ``--problems DIR`` or
``LAGRADE_PROBLEMS`` without touching the engine. ``LAGRADE_DATA=DIR`` names the data root itself:
a platform's grader image holds the engine alone, and its problems come from the platform's private
course files (PrairieLearn's ``/grade/tests``, docs/deploy.md).
"""

from __future__ import annotations

import os
import re
from functools import lru_cache
from pathlib import Path

from lagrade.problem.spec import Problem, SceneError, SpecError, load_problem_file, scene_line

_PACKAGE = Path(__file__).resolve().parents[1]  # the lagrade package (this is lagrade/problem/)
#: the entry-point group of installed problem data: each names a package whose folder holds
#: ``problems/`` and ``reference_solutions/`` (chapter12/pyproject.toml declares the chapter's)
DATA_GROUP = "lagrade.problem_data"
#: where nothing is: the reference folder of an install without problem data (a student's client)
_NOWHERE = _PACKAGE / "_no_problem_data"
#: a folder holding ``problems/`` (and ``reference_solutions/``) that is the data root, before any other
DATA_ENV = "LAGRADE_DATA"


def data_root() -> Path | None:
    """The folder that holds the bundled ``problems/`` and ``reference_solutions/``: ``LAGRADE_DATA``
    if set (a grader whose image holds no key: the platform hands the data in at grading time), else
    the source checkout of an editable install, else the first installed ``lagrade.problem_data``
    package (by entry-point name), else None. Found without importing anything: a data package runs
    no code.

    One root, never several: the answer jail hides exactly ``reference_dir()`` and ``problem_dirs()``
    (:func:`lagrade.answer.jail.child.secret_dirs`), so a second root's references would be readable
    from site-packages. Other courses' problems come with ``--problems DIR``."""
    setting = os.environ.get(DATA_ENV, "")
    return Path(setting).expanduser().resolve() if setting else _installed_root()


@lru_cache(maxsize=1)
def _installed_root() -> Path | None:
    import importlib.util
    from importlib.metadata import entry_points

    checkout = _PACKAGE.parents[1]  # src/lagrade -> the checkout, in an editable install
    if (checkout / "pyproject.toml").is_file() and (checkout / "problems").is_dir():
        return checkout
    for ep in sorted(entry_points(group=DATA_GROUP), key=lambda e: e.name):
        try:
            spec = importlib.util.find_spec(ep.module)
        except (ImportError, ValueError):
            continue
        for place in (spec.submodule_search_locations or []) if spec is not None else []:
            if (Path(place) / "problems").is_dir():
                return Path(place).resolve()
    return None


data_root.cache_clear = _installed_root.cache_clear  # type: ignore[attr-defined]  # what was cached


def _bundled(name: str) -> Path:
    root = data_root()
    return root / name if root is not None else _NOWHERE / name


def problem_dirs(extra: tuple[Path, ...] = ()) -> list[Path]:
    env = [Path(p) for p in os.environ.get("LAGRADE_PROBLEMS", "").split(os.pathsep) if p]
    return [*extra, *env, _bundled("problems")]


def reference_dir() -> Path:
    """The bundled reference solutions (a folder that does not exist when no problem data is
    installed: a student's client, which checks against a course server)."""
    return _bundled("reference_solutions")


NO_DATA = ("no problem data is installed here: your course server has the problems; read one with "
           "lagrade show ID --server URL --token T (template likewise) and check with lagrade check ID "
           "answer.py --server URL --token T, or name a folder of problem files with --problems DIR")


CACHE_ENV = "LAGRADE_CACHE"


def cache_dir() -> Path | None:
    """Where the reference cache's entries live (:mod:`lagrade.derive.cache`), or None when caching is off."""
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
    if not index:
        raise SpecError(f"no problem '{pid}': {NO_DATA}")
    if pid not in index:
        known = ", ".join(list(index)[:12])
        raise SpecError(f"no problem '{pid}' (known ids: {known}{', ...' if len(index) > 12 else ''}){_where_to_look(pid)}")
    return index[pid]


def _where_to_look(pid: str) -> str:
    """What to change when an id is not found: a course's own problems are found only when named, so
    point at a ``<pid>.toml`` in a ``problems/`` folder here, or at the option."""
    here = Path("problems") / f"{pid}.toml"
    if here.is_file():
        return f"; {here} is here: add --problems problems (or set LAGRADE_PROBLEMS)"
    return "; a course's own problem files are found with --problems DIR (or LAGRADE_PROBLEMS=DIR)"


class SceneFileError(SceneError, SpecError):
    """A problem whose scene cannot be derived: the problem file's fault, not an answer's. Its
    message is one line naming the file and line (:func:`scene_message`)."""


def scene_message(problem: Problem, exc: SceneError, extra: tuple[Path, ...] = ()) -> str:
    """``problems/12.35.toml:30: the scene uses effects it does not declare ...``: one line. The file
    is named only when ``problem`` is the one read from it (a problem made in memory has none)."""
    try:
        path = problem_path(problem.id, extra)
        own = load_problem(path) == problem
    except (KeyError, OSError, ValueError):  # SpecError is a ValueError
        own = False
    if not own:
        return f"problem {problem.id}: {exc}"
    line = scene_line(path, exc.system, exc.field) if getattr(exc, "field", None) else None
    return f"{path}:{line}: {exc}" if line else f"{path}: {exc}"


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
