"""What the bulk tests check a graded class against: the gradebook's rows and the generated
expectations (a module of its own: tests/server has a conftest too, and one name would shadow the other)."""

from __future__ import annotations

import sqlite3
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))

import classgen  # noqa: E402


def stored(db: Path) -> tuple[dict, dict]:
    con = sqlite3.connect(db)
    con.row_factory = sqlite3.Row
    subs = {(r["student"], r["problem"]): dict(r) for r in con.execute("SELECT * FROM submissions")}
    parts: dict = {}
    for r in con.execute("SELECT * FROM parts"):
        parts.setdefault((r["student"], r["problem"]), {})[r["part"]] = dict(r)
    con.close()
    return subs, parts


def assert_expected(db: Path, expected: list[classgen.Expected]) -> None:
    """Every file got exactly the score its construction implies; broken/hostile ones 0 with a reason."""
    subs, parts = stored(db)
    assert len(subs) == len(expected)
    wrong = []
    for e in expected:
        row, ps = subs[(e.student, e.problem)], parts[(e.student, e.problem)]
        weights = classgen.part_weights(e.problem)
        assert set(ps) == set(weights)
        if e.expect is None:
            ok = row["score"] == 0 and all(p["verdict"] in ("invalid", "missing") and p["feedback"] for p in ps.values())
            # the reason: why the file could not be used, or why its parts are invalid / missing
            ok = ok and bool(row["reason"] or any(p["verdict"] == "invalid" for p in ps.values())
                             or all(p["verdict"] == "missing" for p in ps.values()))
        else:
            ok = all(abs(ps[p]["score"] - weights[p] * f) < 1e-5 for p, f in e.expect.items())
            ok = ok and abs(row["score"] - e.score(weights)) < 1e-5
        if not ok:
            wrong.append(f"{e.student}/{e.problem} ({e.variant}): score {row['score']}, status {row['status']}, "
                         f"reason {row['reason']!r}, parts {[(k, v['verdict'], v['score']) for k, v in ps.items()]}")
    assert not wrong, "\n".join(wrong)
