"""A hostile corpus: each file gets a clear verdict, nothing outside the sandbox changes, the run goes on."""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

import classgen
from classcheck import stored

from lagrade.uses.bulk.assignment import parse_assignment
from lagrade.uses.bulk.runner import grade_folder

REPO = classgen.REPO


def _tree(path: Path) -> dict[str, str]:
    out = {}
    for p in sorted(path.rglob("*")):
        if p.is_file() and not p.is_symlink():
            out[str(p.relative_to(path))] = hashlib.sha256(p.read_bytes()).hexdigest()
        else:
            out[str(p.relative_to(path))] = "dir" if p.is_dir() else "other"
    return out


def test_hostile_corpus(tmp_path, sentinel):
    root = tmp_path / "submissions"
    corpus = classgen.hostile_sources(sentinel)
    for name, src in corpus.items():
        (root / Path(name).stem).mkdir(parents=True)
        (root / Path(name).stem / "12.43.py").write_text(src)
    # one honest student after them: the run goes on
    (root / "zz_honest").mkdir()
    (root / "zz_honest" / "12.43.py").write_text((REPO / "reference_solutions/12.43/answer.py").read_text())
    db = tmp_path / "out" / "hw.sqlite"
    db.parent.mkdir()
    a = parse_assignment({"name": "hostile", "limits": {"cpu_seconds": 1, "wall_seconds": 4, "memory_mb": 300},
                          "problems": [{"id": "12.43"}]})
    before_subs = _tree(root)
    before_refs = _tree(REPO / "reference_solutions")
    before_tmp = set(os.listdir(tmp_path))
    cwd_before = set(os.listdir("."))

    report = grade_folder(root, a, db, workers=2)

    assert report.todo == len(corpus) + 1
    subs, parts = stored(db)
    unclear = []
    for name in corpus:
        row, ps = subs[(Path(name).stem, "12.43")], parts[(Path(name).stem, "12.43")]
        clear = row["score"] == 0 and all(p["verdict"] in ("invalid", "missing") and p["feedback"] for p in ps.values())
        if row["outcome"] == "failed":
            clear = clear and len(row["reason"]) > 10 and row["status"] in (
                "rejected", "timeout", "memory", "error", "syntax", "crashed")
        else:  # ran to the end without binding anything usable (printing junk, exiting early)
            clear = clear and all(p["verdict"] == "missing" for p in ps.values())
        if not clear:
            unclear.append(f"{name}: {row['outcome']} {row['status']} {row['reason']!r} "
                           f"{[(k, v['verdict'], v['score']) for k, v in ps.items()]}")
    assert not unclear, "\n".join(unclear)
    honest = subs[("zz_honest", "12.43")]
    assert honest["score"] == honest["max_score"] == 3

    # the statuses say what happened
    status = {name: subs[(Path(name).stem, "12.43")]["status"] for name in corpus}
    assert status["while_true.py"] == "timeout" and status["try_swallow.py"] in ("rejected", "timeout")
    assert status["memory_bomb.py"] == "memory" and status["memory_grow.py"] in ("memory", "timeout")
    assert status["import_os.py"] == status["subprocess.py"] == status["socket.py"] == "rejected"
    assert status["open_read_reference.py"] == status["subclasses.py"] == "rejected"
    assert "RecursionError" in subs[("deep_recursion", "12.43")]["reason"]

    # nothing outside the sandbox changed
    assert _tree(root) == before_subs
    assert _tree(REPO / "reference_solutions") == before_refs
    assert set(os.listdir(tmp_path)) == before_tmp
    assert set(os.listdir(".")) == cwd_before
    assert {p.name for p in db.parent.iterdir()} <= {"hw.sqlite", "hw.sqlite-shm", "hw.sqlite-wal", "hw.sqlite.lock"}
    # no reference text leaked into a stored answer
    secret = "p_theta**2 / (2 * m * l**2)"
    assert all(secret not in (p.get("answer_text") or "") for ps in parts.values() for p in ps.values())
