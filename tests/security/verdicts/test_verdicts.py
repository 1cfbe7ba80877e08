"""Issue 31, item 7: answers built to fool the *verdict* get no credit on the part they target, and
honest controls keep full marks.

Each file ``<problem>/<family>-<name>.py|.toml`` is graded as ``lagrade check <problem> FILE --json
--accuracy A --grading-seconds 60`` grades it (``lagrade.check``, the CLI's own path; an answer.py
runs in the jail). ``no-credit``: the target part's score is 0 and its verdict ``incorrect`` or
``invalid``; ``full-marks``: its score is its maximum. The ``hints`` family runs with ``--hints``, and
its feedback must not match the file's ``# leak:`` regular expression (issue 31, item 6). Every file
runs under ``default``; the first answer.py and answer.toml of each family also under ``strict`` and
``fast``. The fast tier runs the honest controls and each family's first two files under ``default``
(about 15 s on 2 cores); ``pytest -m slow tests/security/verdicts`` runs the rest.

The table for a before/after report: ``python tests/security/verdicts/verdicts_harness.py --markdown``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from verdicts_harness import FAMILIES, cases, holds, preset_subset, run  # noqa: E402

CASES = cases()
SUBSET = preset_subset(CASES)


def test_the_suite_covers_what_issue_31_asks():
    attacks = [c for c in CASES if c.expect == "no-credit"]
    honest = [c for c in CASES if c.expect == "full-marks"]
    assert len([c for c in attacks if c.family != "hints"]) >= 40 and 6 <= len(honest) <= 40
    assert len({c.problem for c in attacks}) >= 8
    assert {c.family for c in attacks} == FAMILIES - {"honest"}
    assert all(c.family == "honest" for c in honest) and all(c.family != "honest" for c in attacks)
    assert {c.path.suffix for c in attacks} == {".py", ".toml"}
    assert any("'\\" in c.path.read_text() for c in attacks), "no LaTeX attack"


def _check(case, accuracy):
    out = run(case, accuracy)
    assert holds(case, out), (
        f"{case.name} [{accuracy}] targets {case.target} ({case.family}: {case.why}); expected {case.expect}, "
        f"got {out.verdict} {out.score:g}/{out.max_score:g} by {out.method}: {out.feedback}")


#: The fast tier: every honest control, and the first answer.py and answer.toml of each family; the
#: slow tier runs every other file (a wrong answer flagged by the screen pays a failed proof, ~2 s).
FAST = {c.name for c in SUBSET} | {c.name for c in CASES if c.family == "honest"}


@pytest.mark.parametrize("case", [pytest.param(c, id=c.name, marks=() if c.name in FAST else pytest.mark.slow)
                                  for c in CASES])
def test_default(case):
    _check(case, "default")


@pytest.mark.slow
@pytest.mark.parametrize("accuracy", ["strict", "fast"])
@pytest.mark.parametrize("case", SUBSET, ids=[c.name for c in SUBSET])
def test_other_presets(case, accuracy):
    _check(case, accuracy)
