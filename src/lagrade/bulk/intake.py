"""From what an LMS hands over to the submissions layout (``<student>/<problem-id>.py``).

Students name files as they like: ``12_22.py``, ``12.22 (1).py``, ``12.22.PY``, ``hw7-12.22.py``.
Such a near-miss is matched to its problem and *reported*, never left for a silent zero; a file
that matches no problem is reported too. Used by ``lagrade import`` (Canvas's flat downloads,
Gradescope's export folders) and by the Gradescope autograder (one submission's files).

Canvas names each file of a "Download Submissions" zip ``<name>_<user id>_<attachment id>_<file>``
(``studenttest_3143_207797_zipsubmission.zip`` in instructure/canvas-lms#2406)
(``<name>_late_<user id>_...`` when late; the name is the student's sortable name, lower case,
without spaces or punctuation) and a resubmitted file ``<file>-<n>.py``; the older
``<login>_<submission id>_<file>`` form is read as well. Gradescope's "Export Submissions" holds
one ``submission_<id>/`` folder per submission and ``submission_metadata.yml`` naming its submitters.
"""

from __future__ import annotations

import re
import shutil
import stat
from dataclasses import dataclass, field
from pathlib import Path

ANSWER_SUFFIXES = (".py", ".toml")
#: copies and resubmissions: "12.22 (1)", "12.22(2)", "12.22-1" (Canvas), "12.22 copy"
_COPY = re.compile(r"(\s*\(\d+\)|-\d+|\s+copy)$", re.IGNORECASE)
_SAFE_STUDENT = re.compile(r"[^A-Za-z0-9._@+-]")


@dataclass(frozen=True)
class Match:
    problem: str
    exact: bool  # the name is <problem-id>.py or .toml as it should be


def _pattern(pid: str) -> re.Pattern:
    """``12.22`` -> 12[._ -]22 (any case), at the end of the stem, after its start or a non-alphanumeric."""
    pieces = [re.escape(x) for x in re.split(r"[._\- ]", pid)]
    return re.compile(r"(?:^|(?<=[^A-Za-z0-9]))" + r"[._\- ]".join(pieces) + r"$", re.IGNORECASE)


def match_name(name: str, ids: list[str]) -> Match | None:
    """The problem a file name is for, exact or near miss; None if none (or several equally) fit."""
    p = Path(name)
    suffix = p.suffix
    if suffix.lower() not in ANSWER_SUFFIXES:
        return None
    stem = p.name[: -len(suffix)].strip()
    if suffix in ANSWER_SUFFIXES and stem in ids:
        return Match(stem, True)
    for candidate in (stem, _COPY.sub("", stem).strip()):
        if candidate in ids:
            return Match(candidate, False)
        hits = [pid for pid in ids if _pattern(pid).search(candidate)]
        if hits:
            best = max(len(h) for h in hits)
            longest = [h for h in hits if len(h) == best]
            return Match(longest[0], False) if len(longest) == 1 else None
    return None


@dataclass
class Found:
    """One student's answer files: the one chosen per problem, and what a person should know."""

    chosen: dict[str, Path] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


def _regular(path: Path) -> bool:
    try:
        return stat.S_ISREG(path.lstat().st_mode)
    except OSError:
        return False


def choose(files: list[Path], ids: list[str], shown=lambda p: p.name) -> Found:
    """Per problem, the best file among ``files`` (exact name first, then the shallowest, then by name)."""
    out = Found()
    matched: dict[str, list[tuple[bool, Path]]] = {}
    for f in files:
        m = match_name(f.name, ids)
        if m is None:
            if f.suffix.lower() in ANSWER_SUFFIXES:
                out.notes.append(f"{shown(f)} matches no problem of this assignment (expected "
                                 f"{', '.join(i + '.py' for i in ids)}): not graded")
            continue
        matched.setdefault(m.problem, []).append((m.exact, f))
    for pid in ids:
        if pid not in matched:
            continue
        ranked = sorted(matched[pid], key=lambda e: (not e[0], len(e[1].parts), str(e[1])))
        exact, best = ranked[0]
        out.chosen[pid] = best
        if not exact:
            out.notes.append(f"{shown(best)} was graded as problem {pid} (the expected name is {pid}.py or {pid}.toml)")
        if len(ranked) > 1:
            out.notes.append(f"several files for problem {pid}: graded {shown(best)}; not graded: "
                             + ", ".join(shown(f) for _, f in ranked[1:]))
    return out


def find_answers(folder: Path, ids: list[str]) -> Found:
    """The answer files of one submission folder, at any depth (symbolic links are never followed)."""
    files = sorted(p for p in folder.rglob("*") if _regular(p) and not any(x.startswith(".") for x in
                                                                          p.relative_to(folder).parts))
    return choose(files, ids, lambda p: str(p.relative_to(folder)))


# ---------------------------------------------------------------------------------------- import

_CANVAS = re.compile(r"^(?P<name>[^_]+)_(?:(?:late|LATE)_)?(?P<uid>\d+)_(?P<aid>\d+)_(?P<file>.+)$")
_CANVAS_SHORT = re.compile(r"^(?P<name>[^_]+)_(?:(?:late|LATE)_)?(?P<sid>\d+)_(?P<file>.+)$")


@dataclass
class ImportReport:
    copied: list[tuple[str, str]] = field(default_factory=list)  # (source, destination), relative
    notes: list[str] = field(default_factory=list)                # near misses, several files, no match
    students: list[str] = field(default_factory=list)
    kind: str = ""


def _student_folder(name: str) -> str:
    s = _SAFE_STUDENT.sub("_", name.strip()).strip("._") or "student"
    return s[:200]


def parse_canvas_name(name: str, ids: list[str]) -> tuple[str, str, str] | None:
    """(student, canvas user id or "", original file name) of a Canvas download's file name.

    Both forms are tried; the one whose file part names a problem wins (``jdoe_555_12_22.py`` is
    jdoe's ``12_22.py``, not a user 555's ``22.py``)."""
    forms = []
    if m := _CANVAS.match(name):
        forms.append((m["name"], m["uid"], m["file"]))
    if m := _CANVAS_SHORT.match(name):
        forms.append((m["name"], "", m["file"]))
    for form in forms:
        if match_name(form[2], ids):
            return form
    return forms[0] if forms else None


def _gradescope_metadata(path: Path) -> dict[str, str]:
    """submission folder -> the first submitter's sid (else email, else name), from the YAML's lines.

    Read line by line (the file is Ruby-flavoured YAML with ``:key:`` symbols), no YAML library."""
    out: dict[str, str] = {}
    current = None
    fields: dict[str, str] = {}

    def flush() -> None:
        if current:
            who = fields.get("sid") or (fields.get("email") or "").split("@")[0] or fields.get("name")
            if who:
                out[current] = who

    for line in path.read_text(encoding="utf-8", errors="replace").splitlines():
        if m := re.match(r"^(submission_\d+):\s*$", line):
            flush()
            current, fields = m[1], {}
        elif current and (m := re.match(r"^\s*-?\s*:(sid|email|name):\s*['\"]?(.*?)['\"]?\s*$", line)):
            fields.setdefault(m[1], m[2])
    flush()
    return out


def import_downloads(source: Path, ids: list[str], dest: Path, roster: dict[str, dict[str, str]] | None = None
                     ) -> ImportReport:
    """Copy the answer files of an LMS download into ``dest/<student>/<problem-id>.<ext>``.

    ``roster`` (``exports.read_roster``): a Canvas user id found there names the folder after the
    roster's ``SIS Login ID`` (else its ``ID``), so that the Canvas export finds the student."""
    source, dest = Path(source), Path(dest)
    if not source.is_dir():
        raise FileNotFoundError(f"{source}: not a folder (unzip the LMS download first)")
    report = ImportReport()
    groups: dict[str, list[Path]] = {}
    shown: dict[Path, str] = {}
    meta = next(iter(sorted(source.rglob("submission_metadata.yml"))), None)
    subs = sorted(p for p in source.rglob("submission_*") if p.is_dir() and not p.is_symlink()
                  and re.fullmatch(r"submission_\d+", p.name))
    if meta is not None or subs:
        report.kind = "gradescope"
        names = _gradescope_metadata(meta) if meta else {}
        for folder in subs:
            student = _student_folder(names.get(folder.name, folder.name))
            for f in sorted(folder.rglob("*")):
                if _regular(f):
                    groups.setdefault(student, []).append(f)
                    shown[f] = str(f.relative_to(source))
    else:
        report.kind = "canvas"
        for f in sorted(source.iterdir()):
            if not _regular(f) or f.name.startswith("."):
                continue
            parsed = parse_canvas_name(f.name, ids)
            if parsed is None:
                report.notes.append(f"{f.name}: not a Canvas download name (<name>_<user id>_<id>_<file>): not imported")
                continue
            name, uid, original = parsed
            row = (roster or {}).get(uid) if uid else None
            student = _student_folder((row.get("SIS Login ID") or row.get("ID") or name) if row else name)
            renamed = f.with_name(original)
            groups.setdefault(student, []).append(f)
            shown[f] = f.name
            shown[renamed] = f.name
    for student, files in sorted(groups.items()):
        # Canvas: match on the original file name, copy from the download's file
        originals = {}
        for f in files:
            parsed = parse_canvas_name(f.name, ids) if report.kind == "canvas" else None
            originals[f.with_name(parsed[2]) if parsed else f] = f
        found = choose(list(originals), ids, lambda p: shown.get(originals.get(p, p), p.name))
        report.notes += [f"{student}: {n}" for n in found.notes]
        if not found.chosen:
            report.notes.append(f"{student}: no answer file for any problem of this assignment")
            continue
        report.students.append(student)
        (dest / student).mkdir(parents=True, exist_ok=True)
        for pid, f in found.chosen.items():
            src = originals[f]
            target = dest / student / f"{pid}{f.suffix.lower()}"
            for other in ANSWER_SUFFIXES:  # a .toml from an earlier import must not sit beside the new .py
                stale = dest / student / f"{pid}{other}"
                if other != f.suffix.lower() and stale.exists():
                    stale.unlink()
            try:
                shutil.copyfile(src, target)
            except OSError as exc:  # an unreadable file is said, and the import goes on
                report.notes.append(f"{student}: {shown.get(src, src.name)} cannot be read ({exc.strerror or exc}): "
                                    "not imported")
                continue
            report.copied.append((shown.get(src, src.name), str(target.relative_to(dest))))
    return report
