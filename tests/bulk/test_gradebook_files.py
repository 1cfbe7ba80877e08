"""A path that is not a gradebook, given to ``grade --db``, ``export`` or ``report``: one line on
stderr naming the file and what to do, exit 2, no traceback, and the file left exactly as it was."""

from __future__ import annotations

import hashlib
import os
import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import classgen
import pytest
from click.testing import CliRunner

from lagrade.uses.bulk.store import Key, Store
from lagrade.cli.bulk import export, grade, report

REPO = classgen.REPO
KINDS = ["text", "random bytes", "truncated", "directory", "another program's database", "unreadable"]
HINTS = {"grade": "give another --db path or move it away", "export": "give the database that 'lagrade grade' wrote",
         "report": "give the database that 'lagrade grade' wrote"}
WHY = {"text": "file is not a database", "random bytes": "file is not a database",
       "truncated": "database disk image is malformed", "directory": "it is a folder",
       "another program's database": "an SQLite database of something else", "unreadable": "Permission denied"}


@pytest.fixture(scope="module")
def real_gradebook(tmp_path_factory) -> bytes:
    """The bytes of a gradebook with 200 graded rows, written through the Store (to cut in half)."""
    db = tmp_path_factory.mktemp("real") / "hw.sqlite"
    with Store(db, lock=True) as store:
        store.set_meta("assignment", '{"name": "hw", "problems": [{"id": "12.43"}]}')
        for i in range(200):
            store.record(student=f"s{i:03d}", problem="12.43", path=f"s{i:03d}/12.43.py", key=Key("f", "g", "v"),
                         outcome="graded", status="ok", reason="", score=3.0, max_score=3.0, problems=[], stdout="",
                         source="H = 1\n" * 300, seconds=0.1,
                         parts=[{"part": "H", "verdict": "correct", "score": 1.0, "max_score": 1.0, "method": "exact",
                                 "feedback": "correct"}])
    return db.read_bytes()


def _make(kind: str, folder: Path, real: bytes) -> Path:
    path = folder / "hw7.sqlite"
    if kind == "text":
        path.write_text("student,score\nada,3\n")
    elif kind == "random bytes":
        path.write_bytes(os.urandom(8192))
    elif kind == "truncated":
        path.write_bytes(real[: len(real) // 2])
    elif kind == "directory":
        path.mkdir()
        (path / "keep.txt").write_text("mine\n")
    elif kind == "another program's database":
        con = sqlite3.connect(path)
        con.execute("CREATE TABLE photos (id INTEGER PRIMARY KEY, name TEXT)")
        con.execute("INSERT INTO photos(name) VALUES ('holiday.jpg')")
        con.commit()
        con.close()
    elif kind == "unreadable":
        path.write_bytes(real)
        path.chmod(0)
    return path


def _snapshot(folder: Path) -> dict[str, tuple]:
    """Every file under ``folder`` (the gradebook, what sits next to it): size, time, content hash."""
    out = {}
    for p in sorted(folder.rglob("*")):
        if p.is_file():
            st = p.stat()
            try:
                digest = hashlib.sha256(p.read_bytes()).hexdigest()
            except PermissionError:
                digest = None
            out[str(p.relative_to(folder))] = (st.st_size, st.st_mtime_ns, st.st_mode, digest)
    return out


def _class(folder: Path) -> tuple[Path, Path]:
    (folder / "submissions" / "ada").mkdir(parents=True)
    shutil.copyfile(REPO / "reference_solutions/12.43/answer.py", folder / "submissions" / "ada" / "12.43.py")
    hw = folder / "hw.toml"
    hw.write_text('name = "hw7"\n[[problems]]\nid = "12.43"\n')
    return folder / "submissions", hw


def _args(command: str, db: Path, root: Path, hw: Path) -> list[str]:
    if command == "grade":
        return ["grade", str(root), "-a", str(hw), "--db", str(db), "-j", "1", "--no-summary", "--no-progress"]
    return [command, str(db)] + (["--format", "csv"] if command == "export" else [])


def _run(command: str, args: list[str], without_dac_override: bool) -> tuple[int, str, str]:
    if not without_dac_override:
        res = CliRunner().invoke({"grade": grade, "export": export, "report": report}[command], args[1:])
        assert not (res.exception and not isinstance(res.exception, SystemExit)), repr(res.exception)
        return res.exit_code, res.stdout, res.stderr
    # root reads every file: the unreadable gradebook is tried by a root without the two capabilities
    # that override file permissions (dropped from the bounding set, so lost at exec)
    p = subprocess.run([sys.executable, "-m", "lagrade", *args], capture_output=True, text=True, timeout=300,
                       preexec_fn=_drop_dac_override)
    return p.returncode, p.stdout, p.stderr


def _drop_dac_override() -> None:
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    for cap in (1, 2):  # CAP_DAC_OVERRIDE, CAP_DAC_READ_SEARCH
        if libc.prctl(24, cap, 0, 0, 0) != 0:  # PR_CAPBSET_DROP
            raise OSError(ctypes.get_errno(), "prctl(PR_CAPBSET_DROP)")


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("command", ["grade", "export", "report"])
def test_a_path_that_is_not_a_gradebook_gets_one_line_and_is_left_alone(command, kind, real_gradebook, tmp_path):
    root, hw = _class(tmp_path)
    db = _make(kind, tmp_path, real_gradebook)
    before = _snapshot(tmp_path)
    code, out, err = _run(command, _args(command, db, root, hw), kind == "unreadable" and os.geteuid() == 0)
    after = _snapshot(tmp_path)
    lock = after.pop(f"{db.name}.lock", None)  # grade takes the one-writer lock before it opens the file
    assert lock is None or (command == "grade" and lock[0] == 0)

    assert code == 2, (out, err)
    assert "Traceback" not in out + err
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(f"lagrade: {db} "), err
    assert WHY[kind] in lines[0] and lines[0].endswith(HINTS[command]), lines[0]
    assert after == before, "the file, or what is next to it, changed"
    if kind == "directory":
        assert db.is_dir() and (db / "keep.txt").read_text() == "mine\n"


def test_a_missing_gradebook_is_one_line_too(tmp_path):
    for command in (export, report):
        res = CliRunner().invoke(command, [str(tmp_path / "hw7.sqlite")])
        assert res.exit_code == 2 and res.stderr == \
            f"lagrade: {tmp_path / 'hw7.sqlite'} does not exist; give the database that 'lagrade grade' wrote\n"
    assert not (tmp_path / "hw7.sqlite").exists()


def test_a_damaged_page_read_later_is_one_line(real_gradebook, tmp_path):
    # the header and the first pages are whole: the damage shows only when the rows are read
    db = tmp_path / "hw7.sqlite"
    data = bytearray(real_gradebook)
    data[len(data) // 2:] = os.urandom(len(data) - len(data) // 2)
    db.write_bytes(bytes(data))
    root, hw = _class(tmp_path)
    for command in ("grade", "export", "report"):  # grade reads every page before it writes one
        code, out, err = _run(command, _args(command, db, root, hw), False)
        assert code == 2 and "Traceback" not in out + err, (out, err)
        assert err.startswith(f"lagrade: {db} is not a lagrade gradebook (") and err.count("\n") == 1, err
        assert err.endswith(HINTS[command] + "\n")
    assert db.read_bytes() == bytes(data)
