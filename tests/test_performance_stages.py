"""Issue 48's measuring and its cuts: benchmarks/stages.py charges each stage its own CPU only, and the
web process takes a value's read-back from its grader instead of parsing and printing it again."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))

import stages  # noqa: E402


def _spin(seconds: float) -> None:
    end = time.process_time() + seconds
    while time.process_time() < end:
        pass


def test_a_stage_is_charged_its_own_cpu_not_what_runs_inside_it():
    timers = stages.Timers()
    inner = timers.wrap(lambda: _spin(0.06), "inner")
    outer = timers.wrap(lambda: (_spin(0.03), inner()), "outer")
    outer()
    spent = timers.report()
    assert 0.05 <= spent["inner"] < 0.2, spent
    assert 0.025 <= spent["outer"] < 0.055, spent  # without the inner stage's 0.06 s


def test_the_server_uses_the_graders_read_back_without_parsing_it_again(monkeypatch):
    from lagrade.uses.server import grading

    def never(*args):
        raise AssertionError("read back again in the web process")

    monkeypatch.setattr(grading, "_read_back", never)
    part = {"part": "L", "verdict": "correct", "score": 1.0, "max_score": 1.0, "method": "exact", "feedback": "ok",
            "answer_text": "m*x'**2/2", "answer_mathml": "<math/>", "read_back": [r"\frac{m \dot{x}^{2}}{2}", "m·ẋ²/2"]}
    result = {"problem": "12.1", "score": 1.0, "max_score": 1.0, "parts": [part], "problems": [],
              "status": "ok", "outcome": "graded"}
    out = grading.check_json(result, problem=object())
    assert out["parts"][0]["read_as"] == r"\frac{m \dot{x}^{2}}{2}"
    assert out["read_as_text"] == {"L": "m·ẋ²/2"}
    assert "read_back" not in out["parts"][0]


def test_a_result_without_the_graders_read_back_is_read_back_here(monkeypatch):
    from lagrade.uses.server import grading

    monkeypatch.setattr(grading, "_read_back", lambda problem, text: ("LATEX", "TEXT"))
    part = {"part": "L", "verdict": "correct", "score": 1.0, "max_score": 1.0, "method": "exact", "feedback": "ok",
            "answer_text": "m*x'**2/2"}
    result = {"problem": "12.1", "score": 1.0, "max_score": 1.0, "parts": [part], "problems": [],
              "status": "ok", "outcome": "graded"}
    out = grading.check_json(result, problem=object())
    assert out["parts"][0]["read_as"] == "LATEX" and out["read_as_text"] == {"L": "TEXT"}


@pytest.mark.parametrize("size", [(2, 5), (3, 3), (4, 7)])
def test_the_pivoted_columns_are_those_of_lapacks_pivoted_qr(size):
    """compare.certify.pivoted_columns replaced scipy.linalg.qr(pivoting=True) on the check path."""
    import numpy as np
    from scipy.linalg import qr

    from lagrade.compare.certify import pivoted_columns

    rng = np.random.default_rng(sum(size))
    for _ in range(50):
        a = rng.normal(size=size) * rng.choice([1e-3, 1.0, 1e3], size=size[1])
        k = min(size)
        assert sorted(pivoted_columns(a)[:k]) == sorted(qr(a, pivoting=True)[2][:k])
