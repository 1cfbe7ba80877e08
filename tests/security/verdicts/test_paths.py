"""Issue 42, "Done when": every file of the verdict suite gets its expected verdict through each path a
grade is given by (``lagrade check``, ``lagrade grade`` on a class folder, the course server's check
API) under each accuracy preset (fast, default, strict). A family earning credit through one path or
preset only is a grader bug, so the whole matrix runs (slow tier; ``check`` under ``default`` is
`test_verdicts.test_default`).

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


def _wrong(path: str, preset: str) -> list[str]:
    got = run_path(CASES, path, preset)
    wrong = []
    for case in CASES:
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
    assert not wrong, f"{len(wrong)} of {len(CASES)} files not as expected through {path} under {preset}:\n" + \
        "\n".join(wrong)
