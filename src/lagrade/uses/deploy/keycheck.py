"""Whether something a deployment makes public holds the key: a problem file, a reference solution,
or the problem-data distribution (lagrade-chapter12).

A grader image on a public registry is readable by anyone who pulls it, whatever modes its files
have, so ``lagrade prairielearn build`` checks the image's build context (the Dockerfile and every
file it could COPY, wheels and other archives opened) and the files PrairieLearn serves to students
(``clientFilesQuestion/``) before it says it is done, and refuses with one line when a key is there.
A key is recognised by what it is, not only where it lies: a file equal to one of the bundled or
given problem files or reference solutions, any TOML that reads as a problem file, anything under a
``reference_solutions`` folder, and a package that declares lagrade's problem-data entry point.
"""

from __future__ import annotations

import hashlib
import io
import tarfile
import tomllib
import zipfile
from pathlib import Path, PurePosixPath

from lagrade.uses.deploy.wheel import DeployError

#: the problem-data distribution, by the names its wheel and its install take
DATA_NAMES = ("lagrade_chapter12", "lagrade-chapter12")
#: archives are opened this many levels deep (a wheel in a tarball in a zip)
_DEPTH = 3


class KeyInPublic(DeployError):
    """A public artefact would hold a problem file, a reference solution or the problem data."""


def known_keys(problems_dirs: tuple[Path, ...] = ()) -> dict[str, str]:
    """The SHA-256 of every bundled problem file and reference solution and of every problem file in
    ``problems_dirs``, with what each is (``reference solution 12.43``)."""
    from lagrade.problem.library import problem_dirs, reference_dir

    found: dict[str, str] = {}

    def add(f: Path, what: str) -> None:
        data = f.read_bytes()
        if len(data) >= 32:  # an empty or near-empty file says nothing, and engine files may equal it
            found.setdefault(hashlib.sha256(data).hexdigest(), what)

    for folder in problem_dirs(problems_dirs):
        for f in sorted(Path(folder).glob("*.toml")) if Path(folder).is_dir() else []:
            add(f, f"problem file {f.stem}")
    refs = reference_dir()
    for f in sorted(refs.rglob("*")) if refs.is_dir() else []:
        if f.is_file() and "__pycache__" not in f.parts:
            add(f, f"reference solution {f.parent.name}")
    return found


def _looks_like_problem(data: bytes) -> bool:
    try:
        doc = tomllib.loads(data.decode("utf-8"))
    except (UnicodeDecodeError, tomllib.TOMLDecodeError):
        return False
    return "id" in doc and ("parts" in doc or "systems" in doc)


def what_key(name: str, data: bytes, known: dict[str, str], depth: int = 0) -> str | None:
    """What key the file ``name`` with content ``data`` is or holds (an archive is opened), else None."""
    parts = PurePosixPath(name.replace("\\", "/")).parts
    base = parts[-1] if parts else name
    if "reference_solutions" in parts:
        return "a reference solution"
    if any(base.startswith(d) for d in DATA_NAMES):
        return "the problem-data distribution (lagrade-chapter12)"
    digest = hashlib.sha256(data).hexdigest()
    if digest in known:
        return f"a copy of the {known[digest]}"
    if base.endswith(".toml") and _looks_like_problem(data):
        return "a problem file"
    if base == "Dockerfile" and any(d.encode() in data for d in DATA_NAMES):
        return "a Dockerfile that installs the problem-data distribution (lagrade-chapter12)"
    if base == "entry_points.txt" and b"lagrade.problem_data" in data:
        return "a problem-data package (it declares the lagrade.problem_data entry point)"
    if depth < _DEPTH:
        for member, content in _members(data):
            why = what_key(member, content, known, depth + 1)
            if why is not None:
                return f"{why}, in it as {member}"
    return None


def _members(data: bytes):
    """(name, content) of each file of a zip (wheels) or tar archive; nothing for any other file."""
    buf = io.BytesIO(data)
    if data[:4] == b"PK\x03\x04" and zipfile.is_zipfile(buf):
        with zipfile.ZipFile(buf) as z:
            for info in z.infolist():
                if not info.is_dir():
                    yield info.filename, z.read(info)
        return
    try:
        with tarfile.open(fileobj=io.BytesIO(data)) as t:
            for info in t.getmembers():
                if info.isfile():
                    f = t.extractfile(info)
                    if f is not None:
                        yield info.name, f.read()
    except (tarfile.TarError, EOFError, OSError):
        return


def find_keys(folder: Path, problems_dirs: tuple[Path, ...] = (), known: dict[str, str] | None = None
              ) -> list[str]:
    """``<path relative to folder>: <what key it is>`` for every file of ``folder`` that is or holds one."""
    known = known_keys(problems_dirs) if known is None else known
    found = []
    for f in sorted(Path(folder).rglob("*")):
        if f.is_file():
            rel = f.relative_to(folder).as_posix()
            why = what_key(rel, f.read_bytes(), known)
            if why is not None:
                found.append(f"{rel}: {why}")
    return found


def refuse_keys(folder: Path, what: str, problems_dirs: tuple[Path, ...] = (),
                known: dict[str, str] | None = None) -> None:
    """:class:`KeyInPublic`, one line, when ``folder`` (``what``: the public thing it becomes) holds a key."""
    found = find_keys(folder, problems_dirs, known)
    if found:
        more = f" (and {len(found) - 1} more)" if len(found) > 1 else ""
        raise KeyInPublic(f"refusing to put the key into {what}: {folder / found[0]}{more}; the grader image "
                          "holds the engine alone, and problems and references go to the platform's private "
                          "course files (docs/deploy.md)")
