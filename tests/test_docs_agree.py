"""What the docs state about the code is the code's (issue 44): the accuracy presets' tolerances, read
from `lagrade.compare.trajectory.ACCURACY`; no hard-coded test counts for the tiers (pytest selects them;
a count in prose only drifts); export lines that run as written; a README in its readers' words."""

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


def test_an_export_line_gives_what_its_format_needs():
    """`--format gradescope` needs `--student` (with several students), `--format html` a folder (`-o`):
    a docs line that shows or invites those formats shows them with what they need (issue 44: "also csv,
    gradescope, html" after a canvas line did not)."""
    needs = {"gradescope": "--student", "html": "-o"}
    for page in [ROOT / "README.md", *DOCS.glob("*.md")]:
        for line in page.read_text().splitlines():
            if not line.startswith("lagrade export"):
                continue
            for fmt, option in needs.items():
                if re.search(rf"\b{fmt}\b", line):
                    assert f"--format {fmt}" in line and option in line.split("#")[0], f"{page.name}: {line}"


#: the project's own words for its parts, which a student or instructor reading the README does not know
INTERNAL = ("zygote", "red team", "redteam", "oracle", "tripwire", "seccomp", "landlock", "xreplace", "lambdify")


def test_the_readme_is_in_its_readers_words():
    text = (ROOT / "README.md").read_text().lower()
    assert [w for w in INTERNAL if w in text] == []
    assert len(text.splitlines()) <= 170, "a README read in five minutes: move details to docs/"
