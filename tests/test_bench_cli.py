"""``lagrade bench accuracy``: a table, a CSV and a work-precision PNG (a small sweep, to stay quick)."""

from __future__ import annotations

import csv

from click.testing import CliRunner

from lagrade.cli.bench import bench


def test_bench_accuracy_writes_table_csv_and_png(tmp_path):
    res = CliRunner().invoke(bench, ["accuracy", "12.43", "--out", str(tmp_path), "--tolerances", "1e-4,1e-10",
                                     "--methods", "DOP853,LSODA,symplectic"])
    assert res.exit_code == 0, res.output
    assert "reference: DOP853 at rtol = atol = 1e-13" in res.output
    assert "closed form (elliptic functions) differs by" in res.output
    assert "<- grader default" in res.output
    rows = list(csv.DictReader((tmp_path / "accuracy.csv").open()))
    assert {r["method"] for r in rows} == {"DOP853", "LSODA", "symplectic"}
    assert sum(int(r["grader_default"]) for r in rows) == 1
    for r in rows:
        assert float(r["error"]) < 1e-2 and int(r["rhs_evals"]) > 0
    png = (tmp_path / "accuracy.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


def test_bench_tolerance_range_is_every_decade():
    from lagrade.cli.bench import _tolerances

    assert _tolerances("1e-3..1e-12") == tuple(10.0 ** -e for e in range(3, 13))
