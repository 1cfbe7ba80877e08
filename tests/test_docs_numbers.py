"""Numbers the docs state about the code are the code's (issue 44): the accuracy presets' tolerances,
read from `lagrade.compare.trajectory.ACCURACY`, and no hard-coded test counts for the tiers (pytest
selects them; a count in prose only drifts)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from lagrade.compare.trajectory import ACCURACY

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
PRESETS = ("fast", "default", "strict")


def test_answers_md_gives_the_presets_sample_rtol():
    text = " ".join((DOCS / "answers.md").read_text().split())
    said = re.search(r"`sample_rtol`: (\S+) fast, (\S+) default, (\S+) strict", text)
    assert said, "docs/answers.md no longer says the presets' sample_rtol"
    assert [float(x) for x in said.groups()] == [ACCURACY[p].sample_rtol for p in PRESETS]


def _rows(text: str, header: str) -> dict[str, list[str]]:
    lines = text.splitlines()
    start = lines.index(header)
    rows = {}
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip("|").split("|")]
        rows[cells[0]] = cells[1:]
    return rows


@pytest.mark.parametrize(("header", "fields"), [
    ("| preset | sampled states: `sample_rtol` | integration rtol = atol | trajectory comparison rtol = atol "
     "| trajectories | budget per run |",
     ("sample_rtol", "rtol", "compare_rtol", "trajectories", "max_rhs_evals")),
    ("| preset | integration rtol | comparison rtol | `sample_rtol` |", ("rtol", "compare_rtol", "sample_rtol")),
])
def test_numerics_md_tables_are_the_presets(header, fields):
    rows = _rows((DOCS / "numerics.md").read_text(), header)
    assert set(rows) == set(PRESETS)
    for preset in PRESETS:
        acc = ACCURACY[preset]
        assert [float(x) for x in rows[preset]] == [getattr(acc, f) for f in fields], preset


def test_the_tiers_test_counts_are_not_written_down():
    """`pytest` and `pytest -m slow` select what they select: the docs say how long, not how many."""
    for page in [ROOT / "README.md", *DOCS.glob("*.md")]:
        for line in page.read_text().splitlines():
            if re.search(r"`pytest`|`pytest -m slow`", line):  # the tiers' own commands
                assert not re.search(r"\b\d{3,5} tests\b", line), f"{page.name}: {line[:120]}"
