"""``lagrade bench accuracy``: Markdown, a CSV and a work-precision PNG (a small sweep, to stay quick),
and a one-line error for bad input."""

from __future__ import annotations

import csv

import pytest
from click.testing import CliRunner

from lagrade.cli.bench import bench


def test_bench_accuracy_writes_markdown_csv_and_png(tmp_path):
    res = CliRunner().invoke(bench, ["accuracy", "12.43", "--out", str(tmp_path), "--tolerances", "1e-4,1e-10",
                                     "--trajectories", "2", "--methods", "grading,DOP853", "--markdown"])
    assert res.exit_code == 0, res.output
    assert "reference: scipy Radau at rtol = atol = 1e-13" in res.output
    assert "closed form (elliptic functions) differs by" in res.output
    assert "| **lagrade (grading path, DOP853 compiled)** |" in res.output
    assert "median of 3 runs" in res.output
    rows = list(csv.DictReader((tmp_path / "accuracy.csv").open()))
    assert {r["method"] for r in rows} == {"grading", "DOP853"}
    assert sorted(r["preset"] for r in rows if r["preset"]) == ["default", "fast", "strict"]
    for r in rows:
        assert float(r["error"]) < 1e-2 and int(r["rhs_evals"]) > 0
        assert int(r["calls"]) == (2 if r["method"] == "DOP853" else 1)
    png = (tmp_path / "accuracy.png").read_bytes()
    assert png[:8] == b"\x89PNG\r\n\x1a\n" and len(png) > 10_000


@pytest.mark.parametrize("args, says", [
    (["--methods", "RK23"], "unknown method 'RK23'"),
    (["--tolerances", "1e-4,1e-13"], "between the reference's 1e-13 and 1"),
    (["--tolerances", "fine"], "not a range like 1e-3..1e-12"),
    (["--repeat", "1"], "--repeat"),
    (["99.9"], "no scene 99.9"),
])
def test_bench_accuracy_refuses_bad_input_in_one_line(tmp_path, args, says):
    scene = [] if args[0] == "99.9" else ["12.43"]
    cmd = ["accuracy", *scene, *args, "--out", str(tmp_path), "--no-plot"]
    res = CliRunner().invoke(bench, cmd)
    assert res.exit_code == 2 and says in res.output, res.output
    assert "Traceback" not in res.output and not (tmp_path / "accuracy.csv").exists()


def test_bench_tolerance_range_is_every_decade():
    from lagrade.cli.bench import _tolerances

    assert _tolerances("1e-3..1e-12") == tuple(10.0 ** -e for e in range(3, 13))
