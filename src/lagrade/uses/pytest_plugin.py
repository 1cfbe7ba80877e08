"""A pytest plugin: problem files and answer files are test items.

Instructors test their problems the way this repository tests its own: ``pytest problems
reference_solutions tests/answers`` collects, in whatever folders it is given (any names):

- every problem file (a TOML file with an ``id`` and ``[[parts]]``): it loads, and its scene derives;
- every reference solution ``<id>/answer.(py|toml)``: it scores full marks;
- every golden answer ``<id>/<expected>_<what>.(py|toml)``: ``correct_*`` scores full marks,
  ``wrong_*`` does not or gets an extra part (one the book does not ask, not counted) wrong, and a
  first-line comment ``# expect: L=incorrect, eom=correct`` pins verdicts.

``<id>`` is the folder's name, and it must be a problem that can be found: among the problem files
under the paths pytest was given, in the nearest ``problems/`` folder above the answer, in
``LAGRADE_PROBLEMS``, or among the bundled ones (so a folder that only looks like an id is not
collected). A failure reads like grading feedback (the verdict table), not like a traceback. Turn
the plugin off with ``-p no:lagrade``.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

_EXPECT = re.compile(r"^#\s*expect:\s*(.+)$", re.MULTILINE)


class GradingFailure(Exception):
    """Raised by lagrade items; shown as its message only."""


def _problems_dirs(path: Path) -> tuple[Path, ...]:
    for parent in path.parents:
        candidate = parent / "problems"
        if candidate.is_dir() and any(candidate.glob("*.toml")):
            return (candidate,)
    return ()


def _is_problem_file(path: Path) -> bool:
    if path.suffix != ".toml":
        return False
    head = path.read_text(encoding="utf-8", errors="replace")
    return "[[parts]]" in head and re.search(r"^id\s*=", head, re.MULTILINE) is not None


_SESSION_PROBLEMS = pytest.StashKey[dict]()


def _session_problems(config) -> dict[str, Path]:
    """Problem files under the paths pytest was given, by id (the file's name is its id)."""
    if _SESSION_PROBLEMS not in config.stash:
        found: dict[str, Path] = {}
        for arg in config.args or [str(config.rootpath)]:
            root = Path(arg.split("::")[0])
            files = [root] if root.is_file() else sorted(root.rglob("*.toml")) if root.is_dir() else []
            for f in files:
                if _is_problem_file(f):
                    found.setdefault(f.stem, f.parent)
        config.stash[_SESSION_PROBLEMS] = found
    return config.stash[_SESSION_PROBLEMS]


def _problem_dirs_for(config, pid: str, path: Path) -> tuple[Path, ...] | None:
    """Where problem ``pid`` of an answer at ``path`` is found, or None if it is nowhere."""
    from lagrade.problem.library import problem_ids

    session = _session_problems(config)
    dirs = ((session[pid],) if pid in session else ()) + _problems_dirs(path)
    return dirs if pid in problem_ids(dirs) else None


def _answer_kind(path: Path, config) -> str | None:
    if path.suffix not in (".py", ".toml") or len(path.parts) < 2:
        return None
    if path.stem == "answer":
        kind = "reference"
    elif re.match(r"^(correct|wrong)_", path.stem):
        kind = "golden"
    else:
        return None
    return kind if _problem_dirs_for(config, path.parent.name, path) is not None else None


def pytest_addoption(parser):  # noqa: D103
    parser.addoption("--lagrade-accuracy", default="default", choices=("fast", "default", "strict"),
                     help="grade the golden answers under this accuracy preset (honest answers pass under each)")


def pytest_collect_file(file_path: Path, parent):  # noqa: D103
    if _is_problem_file(file_path):
        return ProblemFile.from_parent(parent, path=file_path)
    kind = _answer_kind(file_path, parent.config)
    if kind:
        return AnswerFile.from_parent(parent, path=file_path, kind=kind)
    return None


#: kinds whose mistakes are read as the scene's expressions (`Mechanics.parse`), with these extra names
_SCENE_MISTAKES = {"lagrangian": False, "eom": False, "hamiltonian": True}


def unreadable_mistakes(problem, refs) -> list[str]:
    """The listed mistakes of L, eom and H parts that cannot be read (a name misspelt): the grader skips
    such a mistake, so a student who makes it would never read its sentence. One line each."""
    out = []
    for part in problem.parts:
        if part.kind not in _SCENE_MISTAKES:
            continue
        mech = refs[part.system]
        extra = [*part.symbols, *((str(p) for p in mech.s.p) if _SCENE_MISTAKES[part.kind] else ())]
        for n, mistake in enumerate(part.mistakes, 1):
            for text in mistake.answer if isinstance(mistake.answer, list) else [mistake.answer]:
                try:
                    mech.parse(str(text), extra)
                except Exception as exc:  # noqa: BLE001 - each reason is reported, none raised
                    out.append(f"part '{part.name}', mistake {n} cannot be read ({str(exc).removeprefix('reference: ')}), "
                                "so it would never be named")
                    break
    return out


class ProblemFile(pytest.File):
    def collect(self):
        yield ProblemItem.from_parent(self, name=f"problem {self.path.stem}")


class ProblemItem(pytest.Item):
    def runtest(self) -> None:
        from lagrade.verdicts.grade import references
        from lagrade.problem.library import load_problem
        from lagrade.derive.reference import SceneError
        from lagrade.problem.spec import SpecError

        try:
            problem = load_problem(self.path)
            for system in problem.systems:
                references(problem)[system.key]
            unread = unreadable_mistakes(problem, references(problem))
        except (SpecError, SceneError) as exc:
            raise GradingFailure(str(exc)) from None
        if unread:
            raise GradingFailure(f"{self.path}: " + "; ".join(unread))

    def repr_failure(self, excinfo):  # noqa: D102
        if isinstance(excinfo.value, GradingFailure):
            return str(excinfo.value)
        return super().repr_failure(excinfo)

    def reportinfo(self):  # noqa: D102
        return self.path, None, self.name


class AnswerFile(pytest.File):
    def __init__(self, *, kind: str, **kwargs):
        super().__init__(**kwargs)
        self.kind = kind

    def collect(self):
        pid = self.path.parent.name
        yield AnswerItem.from_parent(self, name=f"{pid}/{self.path.name}", problem_id=pid, kind=self.kind)


class AnswerItem(pytest.Item):
    def __init__(self, *, problem_id: str, kind: str, **kwargs):
        super().__init__(**kwargs)
        self.problem_id = problem_id
        self.kind = kind

    def expectation(self) -> tuple[bool, dict[str, str]]:
        full = self.kind == "reference" or self.path.stem.startswith("correct_")
        m = _EXPECT.search(self.path.read_text(encoding="utf-8", errors="replace"))
        verdicts = {}
        if m:
            for item in m.group(1).split(","):
                if "=" in item:
                    part, verdict = (s.strip() for s in item.split("=", 1))
                    verdicts[part] = verdict
        return full, verdicts

    def runtest(self) -> None:
        from lagrade.verdicts.grade import check
        from lagrade.problem.library import load_problem
        from lagrade.problem.spec import SpecError

        try:
            problem = load_problem(self.problem_id, _problem_dirs_for(self.config, self.problem_id, self.path) or ())
        except SpecError as exc:
            raise GradingFailure(str(exc)) from None
        result = check(problem, self.path, accuracy=self.config.getoption("--lagrade-accuracy", "default"))
        full, verdicts = self.expectation()
        complaints = []
        if full and not result.full_marks:
            complaints.append(f"expected full marks, got {result.score:g} / {result.max_score:g}")
        wrong_extra = any(p.extra and p.verdict not in ("correct", "missing") for p in result.parts)
        if not full and result.full_marks and not wrong_extra:
            complaints.append("expected a lost mark (this answer is wrong), but it scored full marks")
        got = result.verdicts()
        for part, verdict in verdicts.items():
            if got.get(part) != verdict:
                complaints.append(f"expected {part} to be {verdict}, got {got.get(part, 'no such part')}")
        if complaints:
            raise GradingFailure("; ".join(complaints) + "\n" + str(result))

    def repr_failure(self, excinfo):  # noqa: D102
        if isinstance(excinfo.value, GradingFailure):
            return f"{self.path}: {excinfo.value}"
        return super().repr_failure(excinfo)

    def reportinfo(self):  # noqa: D102
        return self.path, None, self.name
