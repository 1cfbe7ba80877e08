"""Finding the submissions in a class folder: ``<root>/<student>/<problem-id>.py`` (or ``.toml``, or
``.ipynb``: a Jupyter notebook's code cells).

Everything else is *skipped*, with the reason, so that an instructor sees what was not graded:
loose files at the top, nested folders, other extensions, files for problems the assignment does
not list, two answer files (``.py``, ``.toml``, ``.ipynb``) for the same problem, symbolic links (they could point at the
reference solutions or anywhere else on the grading machine), hidden files, unreadable files.
"""

from __future__ import annotations

import hashlib
import os
import re
import stat
from dataclasses import dataclass
from pathlib import Path

from lagrade.answer.reading.suffixes import ANSWER_SUFFIXES

MAX_FILE_BYTES = 1_000_000  # the engine refuses far smaller answer files; this only bounds reading


def max_file_bytes(suffix: str) -> int:
    """The bound on reading one answer file: a notebook holds its outputs (pictures) besides its code."""
    from lagrade.answer.reading.notebook import MAX_NOTEBOOK_BYTES

    return MAX_NOTEBOOK_BYTES if suffix == ".ipynb" else MAX_FILE_BYTES


_STUDENT = re.compile(r"^[^\x00-\x1f/\\]{1,200}$")


@dataclass(frozen=True)
class Submission:
    student: str
    problem: str
    path: Path
    sha256: str
    data: bytes

    @property
    def suffix(self) -> str:
        return self.path.suffix


@dataclass(frozen=True)
class Skipped:
    path: str  # relative to the submissions folder
    reason: str


@dataclass
class Layout:
    submissions: list[Submission]
    skipped: list[Skipped]
    students: list[str]  # every student folder, including those with nothing gradable


def file_hash(data: bytes) -> str:
    return hashlib.sha256(data).hexdigest()


def _near_miss(name: str, problem_ids: list[str]) -> str:
    """A hint for a file named nearly right (``12_22.py``): it is skipped here, never guessed at."""
    from lagrade.uses.bulk.intake import match_name

    m = match_name(name, problem_ids)
    return f" (named like problem {m.problem}: rename it {m.problem}.py, or use 'lagrade import')" if m else ""


def scan(root: Path, problem_ids: list[str]) -> Layout:
    """Every submission under ``root`` for the assignment's problems, and every file skipped."""
    root = Path(root)
    if not root.is_dir():
        raise FileNotFoundError(f"{root}: not a folder")
    wanted = set(problem_ids)
    subs: list[Submission] = []
    skipped: list[Skipped] = []
    students: list[str] = []

    def skip(p: Path, reason: str) -> None:
        skipped.append(Skipped(str(p.relative_to(root)), reason))

    for entry in sorted(root.iterdir()):
        if entry.name == ".lagrade-import.json":  # lagrade import's record of the LMS (intake.MANIFEST)
            continue
        st = entry.lstat()
        if stat.S_ISLNK(st.st_mode):
            skip(entry, "a symbolic link (not followed)")
            continue
        if not stat.S_ISDIR(st.st_mode):
            skip(entry, "not inside a student folder (expected <student>/<problem-id>.py)")
            continue
        if entry.name.startswith("."):
            skip(entry, "a hidden folder")
            continue
        if not _STUDENT.match(entry.name):
            skip(entry, "the folder name cannot be a student id")
            continue
        student = entry.name
        students.append(student)
        found: dict[str, list[Path]] = {}
        for f in sorted(entry.iterdir()):
            fst = f.lstat()
            if stat.S_ISLNK(fst.st_mode):
                skip(f, "a symbolic link (not followed)")
            elif stat.S_ISDIR(fst.st_mode):
                skip(f, "a folder inside a student folder (expected <student>/<problem-id>.py)")
            elif not stat.S_ISREG(fst.st_mode):
                skip(f, "not a regular file")
            elif f.name.startswith("."):
                skip(f, "a hidden file")
            elif f.suffix not in ANSWER_SUFFIXES:
                skip(f, f"not an answer file (expected <problem-id>.py, .toml or .ipynb, got '{f.suffix or f.name}')"
                     + _near_miss(f.name, problem_ids))
            elif f.stem not in wanted:
                skip(f, f"problem '{f.stem}' is not in the assignment" + _near_miss(f.name, problem_ids))
            elif fst.st_size > max_file_bytes(f.suffix):
                skip(f, f"larger than {max_file_bytes(f.suffix) // 1000} kB")
            else:
                found.setdefault(f.stem, []).append(f)
        for pid, files in sorted(found.items()):
            if len(files) > 1:
                for f in files:
                    skip(f, f"{' and '.join(g.name for g in files)} were handed in for problem {pid}; keep one")
                continue
            f = files[0]
            try:
                fd = os.open(f, os.O_RDONLY | os.O_NOFOLLOW)
                with os.fdopen(fd, "rb") as fh:
                    data = fh.read(max_file_bytes(f.suffix) + 1)
            except OSError as exc:
                skip(f, f"cannot be read ({exc.strerror or exc})")
                continue
            subs.append(Submission(student, pid, f, file_hash(data), data))
    return Layout(subs, skipped, students)
