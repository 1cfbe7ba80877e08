"""`lagrade.answer` is both a student's vocabulary and the answers layer's package (its submodules are
the jail and the readers): an answer in the jail gets the vocabulary alone."""

from __future__ import annotations

from pathlib import Path

import pytest

from lagrade.answer.jail.rebuild import decode_value
from lagrade.answer.jail.sandbox import SandboxLimits, run_answer_file

FAST = SandboxLimits(cpu_seconds=4, wall_seconds=15, memory_mb=512)


def _run(tmp_path: Path, text: str):
    path = tmp_path / "answer.py"
    path.write_text(text, encoding="utf-8")
    return run_answer_file(path, ["L"], FAST)


def test_the_vocabulary_works_in_the_jail(tmp_path):
    out = _run(tmp_path, "from lagrade.answer import *\nx = coordinates('x')\nL = dot(x)**2 / 2\n")
    assert out.status == "ok", out
    assert str(decode_value(out.values["L"])) == "Derivative(x(t), t)**2/2"


@pytest.mark.parametrize("reach", [
    "import lagrade.answer as A\nL = A.jail\n",
    "import lagrade.answer as A\nL = A.reading\n",
    "import lagrade.answer\nL = lagrade.answer.jail.child\n",
    "from lagrade.answer import jail\nL = jail\n",
    "from lagrade.answer.jail import child\nL = child\n",
    "import lagrade\nL = lagrade.answer.__dict__['jail']\n",
])
def test_an_answer_never_reaches_the_layers_machinery(tmp_path, reach):
    out = _run(tmp_path, reach)
    assert out.status != "ok", (reach, out)
