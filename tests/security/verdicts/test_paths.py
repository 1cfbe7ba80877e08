"""Issue 42, "Done when": every file of the verdict suite gets its expected verdict through each path a
grade is given by (``lagrade check``, ``lagrade grade`` on a class folder, the course server's check
API) under each accuracy preset (fast, default, strict). A family earning credit through one path or
preset only is a grader bug. ``check`` runs every file under fast and strict (``default`` is
`test_verdicts.test_default`); ``grade`` and ``serve`` reach the same engine through their own
plumbing (class folder, workers, gradebook; HTTP, jobs, database), so they run each family's files of
each form (answer.py, text, LaTeX: the first of each) and every honest control under every preset,
which keeps CI's slow tier inside its budget (the whole matrix is the command below).

The same table, for a report:
``python tests/security/verdicts/verdicts_harness.py --path check,grade,serve --accuracy fast,default,strict``.
"""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).resolve().parent))
from verdicts_harness import cases, holds, run_path  # noqa: E402

CASES = cases()
PRESETS = ("fast", "default", "strict")
MATRIX = [(path, preset) for path in ("check", "grade", "serve") for preset in PRESETS
          if (path, preset) != ("check", "default")]


def _forms(cases):
    """Each family's first file of each form, and every honest control."""
    seen, out = set(), []
    for case in cases:
        form = "py" if case.name.endswith(".py") else ("latex" if "latex" in case.name else "text")
        if case.family == "honest" or (case.family, form) not in seen:
            seen.add((case.family, form))
            out.append(case)
    return out


def _wrong(path: str, preset: str) -> list[str]:
    todo = CASES if path == "check" else _forms(CASES)
    got = run_path(todo, path, preset)
    wrong = []
    for case in todo:
        out = got[case.name]
        if isinstance(out, Exception):
            wrong.append(f"{case.name}: {type(out).__name__}: {out}")
        elif not holds(case, out):
            wrong.append(f"{case.name} targets {case.target} ({case.family}, expect {case.expect}): "
                         f"{out.verdict} {out.score:g}/{out.max_score:g} {out.feedback[:160]}")
    return wrong


@pytest.mark.slow
@pytest.mark.timeout(3600)
@pytest.mark.parametrize(("path", "preset"), MATRIX, ids=[f"{p}-{a}" for p, a in MATRIX])
def test_every_file_through_every_path_under_every_preset(path, preset):
    if path == "serve":
        pytest.importorskip("fastapi")
        pytest.importorskip("httpx")
    wrong = _wrong(path, preset)
    assert not wrong, f"{len(wrong)} files not as expected through {path} under {preset}:\n" + \
        "\n".join(wrong)
