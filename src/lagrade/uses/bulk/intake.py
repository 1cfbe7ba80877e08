"""From what an LMS hands over to the submissions layout (``<student>/<problem-id>.py``).

Students name files as they like: ``12_22.py``, ``12.22 (1).py``, ``12.22.PY``, ``hw7-12.22.py``.
Such a near-miss is matched to its problem and *reported*, never left for a silent zero; a file
that matches no problem is reported too. Used by ``lagrade import`` (Canvas's flat downloads,
Gradescope's export folders) and by the Gradescope autograder (one submission's files).

Canvas names each file of a "Download Submissions" zip ``<name>_<user id>_<attachment id>_<file>``
(``studenttest_3143_207797_zipsubmission.zip`` in instructure/canvas-lms#2406; canvas-lms's
``ContentZipper#get_filename``: ``[name, "LATE" if late, user id].join("_")``, the name with every
non-word character removed and lower-cased, so ``<name>_LATE_<user id>_...`` when late (read in any
case) and a name may hold ``_``); ``anon_<anonymous id>_<attachment id>_<file>`` under anonymous grading; a resubmitted file
``<file>-<n>.py``; the older ``<login>_<submission id>_<file>`` form is read as well. Files are
grouped by Canvas user id, never by name: two students who share a name stay two. Gradescope's
"Export Submissions" holds one ``submission_<id>/`` folder per submission and
``submission_metadata.yml`` naming its submitters. Moodle's "Download all submissions" holds a
folder ``<Full Name>_<participant id>_assignsubmission_file_`` per student (or flat files with
that prefix). A student's ``.zip`` is unpacked.
"""

from __future__ import annotations

import re
import shutil
import stat
import unicodedata
from dataclasses import dataclass, field
from pathlib import Path

from lagrade.answer.reading.suffixes import ANSWER_SUFFIXES

#: copies and resubmissions: "12.22 (1)", "12.22(2)", "12.22-1" (Canvas), "12.22 copy"
_COPY = re.compile(r"(\s*\(\d+\)|-\d+|\s+copy)$", re.IGNORECASE)
#: a student folder keeps letters of any script (``Jan_Novák``), digits and ``._@+-``; the rest is ``_``
_SAFE_STUDENT = re.compile(r"[^\w.@+-]")


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
    """Per problem, the best file among ``files`` (exact name first, then the shallowest, then by name). A
    notebook's checkpoint copy (``.ipynb_checkpoints/``, Jupyter's autosave) is never chosen."""
    out = Found()
    matched: dict[str, list[tuple[bool, Path]]] = {}
    for f in files:
        if ".ipynb_checkpoints" in f.parts:
            continue
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
            out.notes.append(f"{shown(best)} was graded as problem {pid} (the expected name is {pid}.py, {pid}.toml or {pid}.ipynb)")
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

#: the tail of a Canvas download name after the student's name: ``_[late_]<user id>_<attachment id>_<file>``
_CANVAS_TAIL = re.compile(r"_(?:(?P<late>late)_)?(?P<uid>\d+)_(?P<aid>\d+)_(?P<file>.+)$", re.IGNORECASE)
#: anonymous grading: ``[late_]anon_<anonymous id>[_late]_<attachment id>_<file>`` (no name, no user id)
_CANVAS_ANON = re.compile(r"^(?:(?P<late1>late)_)?anon_(?P<anon>[A-Za-z0-9]{1,16})_(?:(?P<late2>late)_)?"
                          r"(?P<aid>\d+)_(?P<file>.+)$", re.IGNORECASE)
_CANVAS_SHORT = re.compile(r"^(?P<name>[^_]+)_(?:(?P<late>late)_)?(?P<sid>\d+)_(?P<file>.+)$", re.IGNORECASE)
#: a student's zip inside a download: at most this many members and bytes are unpacked
ZIP_MAX_MEMBERS = 200
ZIP_MAX_BYTES = 20_000_000


@dataclass(frozen=True)
class CanvasName:
    """What a Canvas "Download Submissions" file name says: whose file (``key``: their Canvas user id,
    ``anon_<id>`` under anonymous grading, else the login of the old form), late or not, and its name."""

    key: str
    name: str        # the name part as Canvas wrote it ("" when anonymous)
    uid: str         # the Canvas user id ("" when anonymous or the old form)
    late: bool
    file: str        # the file's name as the student uploaded it


def canvas_names(name: str) -> list[CanvasName]:
    """Every way ``name`` reads as a Canvas download name, the likeliest first.

    Canvas writes ``<name>[_late]_<user id>_<attachment id>_<file>`` with the student's sortable name
    stripped to word characters and lower-cased (``o_brienmary``: underscores stay) and ``_<digits>_``
    taken out of it, so the first ``_<digits>_<digits>_`` is normally where the name ends; a name that
    ends in ``_<digits>`` makes a later split possible as well, so each one is returned."""
    out: list[CanvasName] = []
    if m := _CANVAS_ANON.match(name):
        # the anonymous id keeps its case: Canvas's ids are case-sensitive, and two that differ only in
        # case are two students
        out.append(CanvasName("anon_" + m["anon"], "", "", bool(m["late1"] or m["late2"]), m["file"]))
    for i, ch in enumerate(name):
        if ch == "_" and i > 0 and (m := _CANVAS_TAIL.match(name, i)):
            who = name[:i]
            if who.lower() == "anon":
                continue
            if who.lower().endswith("_late") and not m["late"]:  # "<name>_late_<uid>": the late marker
                continue
            out.append(CanvasName(m["uid"], who, m["uid"], bool(m["late"]), m["file"]))
    if m := _CANVAS_SHORT.match(name):
        out.append(CanvasName(m["name"], m["name"], "", bool(m["late"]), m["file"]))
    return out


def parse_canvas(name: str, ids: list[str], uids: set[str] = frozenset()) -> CanvasName | None:
    """The reading of a Canvas download name: a Canvas user id the roster knows first, then the first
    one whose file names a problem (``jdoe_555_12_22.py`` is jdoe's ``12_22.py``, not user 555's
    ``22.py``), then the first one."""
    forms = canvas_names(name)
    if not forms:
        return None
    return next((f for f in forms if f.uid and f.uid in uids),
                next((f for f in forms if match_name(f.file, ids)), forms[0]))


def parse_canvas_name(name: str, ids: list[str]) -> tuple[str, str, str] | None:
    """(student, canvas user id or "", original file name): :func:`parse_canvas` as a tuple."""
    f = parse_canvas(name, ids)
    return (f.name or f.key, f.uid, f.file) if f else None


@dataclass
class ImportReport:
    copied: list[tuple[str, str]] = field(default_factory=list)  # (source, destination), relative
    notes: list[str] = field(default_factory=list)                # near misses, several files, no match
    students: list[str] = field(default_factory=list)
    kind: str = ""
    #: student folder -> what the LMS said of them: ``canvas_user_id``, ``name``, ``late``
    lms: dict[str, dict] = field(default_factory=dict)


#: written into the submissions folder by ``lagrade import``; ``lagrade grade`` keeps it in the gradebook
MANIFEST = ".lagrade-import.json"


def _student_folder(name: str) -> str:
    """A folder name for a student: accents kept whole (NFC: ``á`` is one letter, as macOS's
    decomposed ``a`` + accent would otherwise become ``a_``), anything else that is not a letter,
    digit or ``._@+-`` made ``_``."""
    s = _SAFE_STUDENT.sub("_", unicodedata.normalize("NFC", name).strip()).strip("._") or "student"
    return s[:200]


def _member_name(info) -> str:
    """A zip member's name as its writer meant it: a name not flagged UTF-8 is decoded as CP437 by
    Python (the zip standard's default), yet the zips of Moodle and of most tools hold UTF-8 bytes
    without the flag (``Jan NovĂˇk`` for ``Jan Novák``); such a name is read as UTF-8 when it is that."""
    name = info.filename
    if info.flag_bits & 0x800:
        return name
    try:
        return name.encode("cp437").decode("utf-8")
    except (UnicodeEncodeError, UnicodeDecodeError):
        return name


def _unzip(archive: Path, into: Path, shown: str) -> tuple[list[Path], list[str]]:
    """The regular files of a student's zip, unpacked under ``into``; what was left out, said.

    Nothing leaves ``into`` (absolute names, ``..`` and links are refused), and a zip bomb stops at
    :data:`ZIP_MAX_MEMBERS` members or :data:`ZIP_MAX_BYTES` bytes."""
    import zipfile

    notes: list[str] = []
    files: list[Path] = []
    try:
        with zipfile.ZipFile(archive) as z:
            total = 0
            members = [i for i in z.infolist() if not i.is_dir()]
            if len(members) > ZIP_MAX_MEMBERS:
                return [], [f"{shown}: a zip of {len(members)} files (more than {ZIP_MAX_MEMBERS}): not unpacked"]
            for info in members:
                parts = Path(_member_name(info).replace("\\", "/")).parts
                mode = (info.external_attr >> 16) & 0o170000
                if info.filename.startswith("/") or ".." in parts or mode == stat.S_IFLNK or not parts \
                        or parts[0].startswith("__MACOSX"):
                    notes.append(f"{shown}: {info.filename} in the zip is not a plain file inside it: not unpacked")
                    continue
                total += info.file_size
                if total > ZIP_MAX_BYTES:
                    notes.append(f"{shown}: larger than {ZIP_MAX_BYTES // 1_000_000} MB unpacked: the rest not unpacked")
                    break
                target = into.joinpath(*parts)
                target.parent.mkdir(parents=True, exist_ok=True)
                with z.open(info) as src, open(target, "wb") as dst:
                    shutil.copyfileobj(src, dst, 1 << 16)
                files.append(target)
    except (zipfile.BadZipFile, OSError, RuntimeError, NotImplementedError) as exc:
        notes.append(f"{shown}: a zip that cannot be unpacked ({exc}): not imported")
    return files, notes


#: Moodle's "Download all submissions": a folder ``<Full Name>_<participant id>_assignsubmission_file_``
#: per student (``Participant_<id>_...`` with blind marking), or, with "Download submissions in
#: folders" off, flat files ``<Full Name>_<participant id>_assignsubmission_file_<file>``
_MOODLE = re.compile(r"^(?P<name>.*?)_(?P<id>\d+)_assignsubmission_(?P<plugin>[a-z]+)_(?P<file>.*)$")


def _moodle_entries(source: Path) -> list[tuple[Path, str, str, str]]:
    """(file, student's name, participant id, the file's own name) of a Moodle download; [] if it is not one."""
    out = []
    for entry in sorted(source.iterdir()):
        m = _MOODLE.match(entry.name)
        if m is None or entry.is_symlink():
            continue
        name = "" if m["name"].lower() == "participant" else unicodedata.normalize("NFC", m["name"])
        if entry.is_dir() and not m["file"]:
            for f in sorted(entry.rglob("*")):
                if _regular(f) and not any(x.startswith(".") for x in f.relative_to(entry).parts):
                    out.append((f, name, m["id"], f.name))
        elif _regular(entry) and m["file"]:
            out.append((entry, name, m["id"], m["file"]))
    return out


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

    Canvas: files are grouped by Canvas user id (two students who share a name stay two); the folder
    is the roster's ``SIS Login ID`` (else its ``ID``) for a user id on ``roster``
    (``exports.read_roster``), else ``<name>_<user id>`` (``anon_<id>`` under anonymous grading).
    A student's ``.zip`` is unpacked. What the LMS said of each student (Canvas user id, late) is
    written to ``dest/.lagrade-import.json`` for the gradebook."""
    import json
    import tempfile

    source, dest = Path(source), Path(dest)
    if not source.is_dir():
        raise FileNotFoundError(f"{source}: not a folder (unzip the LMS download first)")
    report = ImportReport()
    groups: dict[str, list[Path]] = {}
    shown: dict[Path, str] = {}
    originals: dict[Path, Path] = {}  # the name a file is matched on -> the file to copy
    scratch = Path(tempfile.mkdtemp(prefix="lagrade-import-"))
    try:
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
        elif moodle := _moodle_entries(source):
            report.kind = "moodle"
            for f, name, who, as_named in moodle:
                student = _student_folder(f"{who}_{name}" if name else who)
                report.lms.setdefault(student, {"name": name, "moodle_participant_id": who})
                matched_as = scratch / "names" / str(len(originals)) / as_named
                originals[matched_as] = f
                shown[matched_as] = shown[f] = str(f.relative_to(source))
                groups.setdefault(student, []).append(matched_as)
        else:
            report.kind = "canvas"
            uids = {r.get("ID", "").strip() for r in (roster or {}).values()} - {""}
            by_key: dict[str, list[tuple[Path, CanvasName]]] = {}
            for f in sorted(source.iterdir()):
                if not _regular(f) or f.name.startswith("."):
                    continue
                parsed = parse_canvas(f.name, ids, uids)
                if parsed is None:
                    report.notes.append(f"{f.name}: not a Canvas download name (<name>_<user id>_<id>_<file>): "
                                        "not imported")
                    continue
                by_key.setdefault(parsed.key, []).append((f, parsed))
            taken: dict[str, str] = {}
            for key, entries in sorted(by_key.items()):
                first = entries[0][1]
                row = roster.get(first.uid) if roster and first.uid else None
                if row is not None and row.get("ID", "").strip() != first.uid:
                    row = None  # the roster names this number in another column: not this user
                if row is not None:
                    student = _student_folder(row.get("SIS Login ID") or row.get("ID") or key)
                elif first.uid:
                    student = _student_folder(f"{first.name}_{first.uid}")
                else:
                    student = _student_folder(key)
                # folders that differ only in case are one folder on a case-insensitive disk (macOS)
                if student.casefold() in taken and taken[student.casefold()] != key:
                    student = _student_folder(f"{student}_{key}")
                base, n = student, 2
                while student.casefold() in taken and taken[student.casefold()] != key:
                    student, n = f"{base}_{n}", n + 1
                taken[student.casefold()] = key
                late = any(p.late for _, p in entries)
                report.lms[student] = {"canvas_user_id": first.uid, "name": first.name, "late": late}
                if first.key.startswith("anon_"):
                    report.lms[student]["anonymous_id"] = first.key[len("anon_"):]
                for f, parsed in entries:
                    if parsed.file.lower().endswith(".zip"):
                        into = scratch / f"{len(originals)}"
                        files, notes = _unzip(f, into, f.name)
                        report.notes += [f"{student}: {n}" for n in notes]
                        for g in files:
                            originals[g] = g
                            shown[g] = f"{f.name}:{g.relative_to(into)}"
                            groups.setdefault(student, []).append(g)
                        continue
                    renamed = scratch / "names" / str(len(originals)) / parsed.file
                    originals[renamed] = f
                    shown[renamed] = shown[f] = f.name
                    groups.setdefault(student, []).append(renamed)
        for student, files in sorted(groups.items()):
            if report.kind != "canvas":  # a Gradescope or Moodle submission may hold zips too
                more = []
                for f in files:
                    if f.suffix.lower() == ".zip":
                        into = scratch / f"{len(originals)}-{len(more)}"
                        got, notes = _unzip(f, into, shown.get(f, f.name))
                        report.notes += [f"{student}: {n}" for n in notes]
                        for g in got:
                            shown[g] = f"{shown.get(f, f.name)}:{g.relative_to(into)}"
                        more += got
                files = files + more
            found = choose(files, ids, lambda p: shown.get(p, p.name))
            report.notes += [f"{student}: {n}" for n in found.notes]
            if not found.chosen:
                report.notes.append(f"{student}: no answer file for any problem of this assignment")
                continue
            report.students.append(student)
            (dest / student).mkdir(parents=True, exist_ok=True)
            for pid, f in found.chosen.items():
                src = originals.get(f, f)
                target = dest / student / f"{pid}{f.suffix.lower()}"
                for other in ANSWER_SUFFIXES:  # a .toml from an earlier import must not sit beside the new .py
                    stale = dest / student / f"{pid}{other}"
                    if other != f.suffix.lower() and stale.exists():
                        stale.unlink()
                try:
                    shutil.copyfile(src, target)
                except OSError as exc:  # an unreadable file is said, and the import goes on
                    report.notes.append(f"{student}: {shown.get(f, src.name)} cannot be read "
                                        f"({exc.strerror or exc}): not imported")
                    continue
                report.copied.append((shown.get(f, src.name), str(target.relative_to(dest))))
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    report.lms = {k: v for k, v in report.lms.items() if k in report.students}
    if report.lms:
        dest.mkdir(parents=True, exist_ok=True)
        path = dest / MANIFEST
        old = {}
        try:
            old = json.loads(path.read_text(encoding="utf-8")).get("students", {})
        except (OSError, ValueError, AttributeError):
            pass
        path.write_text(json.dumps({"kind": report.kind, "students": {**old, **report.lms}}, indent=1,
                                   sort_keys=True), encoding="utf-8")
    return report


def read_manifest(folder: Path) -> dict[str, dict]:
    """student folder -> what the LMS said of them (``lagrade import``'s manifest), or {}."""
    import json

    try:
        data = json.loads((Path(folder) / MANIFEST).read_text(encoding="utf-8"))
        students = data.get("students", {})
        return {str(k): dict(v) for k, v in students.items() if isinstance(v, dict)}
    except (OSError, ValueError, AttributeError, TypeError):
        return {}
