"""Student text reaches a terminal printable (issue 43, item 5).

An answer's exception message, a dict key, a key of ``answer.toml``: ``lagrade check``, ``grade`` and
``report`` printed them raw, so an answer could put a command in the instructor's clipboard (OSC 52),
retitle the window, move the cursor and paint a fake green "5 / 5" over the real line (CSI, C1
controls, backspaces), or do the same with rich's own markup (``[bold green]5 / 5[/]`` was rendered
green, its brackets gone). Every such character now prints as a visible escape (``\\x1b``), the markup
literally; ``--json`` stays valid JSON holding the text itself, escaped as JSON escapes it.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

#: OSC 52 (the clipboard), a window title, a cursor move, a colour, rich markup, a C1 CSI, backspaces, a CR
PAYLOAD = ("\x1b]52;c;ZWNobyBwd25lZA==\x07\x1b]0;pwned\x07\x1b[2A\x1b[32m[bold green]5 / 5[/]"
           "\x9b2K\x08\x08\rdone\u202e")
MARKUP = "[bold green]5 / 5[/]"
#: what must never reach a terminal raw: C0 controls but newline, DEL, C1 controls, the bidi override
RAW = re.compile("[\x00-\x09\x0b-\x1f\x7f-\x9f\u202e]")

ANSWER_PY = f"""from lagrade.answer import *
m1, m2, m3, m4, g = parameters("m1 m2 m3 m4 g")
a = {{{PAYLOAD!r}: g, "m2": g, "m3": g, "m4": g}}
raise ValueError({PAYLOAD!r})
"""
#: a key of answer.toml is told back ("... is not a part of problem 12.22; ignored") as written
ANSWER_TOML = 'L = "m1*x_d^2/2"\n' + json.dumps(PAYLOAD) + ' = "x"\n'

ENV = {**os.environ, "COLUMNS": "1000"}  # one line a row: the markup is not wrapped apart


def _lagrade(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lagrade", *args], capture_output=True, text=True, env=ENV,
                          timeout=300)


def _printable(output: str) -> None:
    raw = sorted({f"U+{ord(c):04X}" for c in RAW.findall(output)})
    assert not raw, f"raw control characters reach the terminal: {raw}\n{output[-3000:]}"
    assert "Traceback" not in output, output[-3000:]


def test_printable_shows_every_control_and_keeps_lines():
    from lagrade.verdicts.printable import json_printable, plain, printable

    shown = printable(PAYLOAD + "\nsecond line\tand a tab")
    assert not RAW.search(shown.replace("\t", ""))
    assert "\\x1b]52;c;" in shown and "\\x9b2K" in shown and "\\x08\\x0d" in shown and "\\u202e" in shown
    assert shown.split("\n")[1] == "second line\tand a tab"
    assert plain(MARKUP).plain == MARKUP  # a Text: rich never reads it as markup
    text = json.dumps({"f": PAYLOAD}, ensure_ascii=False)
    escaped = json_printable(text)
    assert not RAW.search(escaped) and json.loads(escaped) == {"f": PAYLOAD}


@pytest.mark.parametrize("name", ["answer.py", pytest.param("answer.toml", marks=pytest.mark.slow)])
def test_check_prints_the_students_text_printable(tmp_path, name):
    path = tmp_path / name
    path.write_text(ANSWER_PY if name.endswith(".py") else ANSWER_TOML, encoding="utf-8")
    proc = _lagrade("check", "12.22", str(path))
    out = proc.stdout + proc.stderr
    _printable(out)
    assert "\\x1b]" in out and MARKUP in out, out  # shown, visibly, and the markup literally
    if name.endswith(".py"):
        assert "\\x1b]52;c;ZWNobyBwd25lZA==\\x07" in out and "\\x9b2K" in out


@pytest.mark.slow
def test_check_json_is_valid_and_holds_the_text_escaped(tmp_path):
    path = tmp_path / "answer.py"
    path.write_text(ANSWER_PY, encoding="utf-8")
    proc = _lagrade("check", "12.22", str(path), "--json")
    _printable(proc.stdout + proc.stderr)
    result = json.loads(proc.stdout)
    feedback = {p["part"]: p["feedback"] for p in result["parts"]}
    assert "\x1b]52;c;ZWNobyBwd25lZA==\x07" in feedback["L"] and "\x9b2K" in feedback["L"]  # the text itself


@pytest.mark.slow
def test_grade_and_report_print_the_students_text_printable(tmp_path):
    subs = tmp_path / "submissions"
    for student, name, text in (("ann", "12.22.py", ANSWER_PY), ("bob", "12.22.toml", ANSWER_TOML)):
        (subs / student).mkdir(parents=True)
        (subs / student / name).write_text(text, encoding="utf-8")
    hw = tmp_path / "hw.toml"
    hw.write_text('name = "hw"\n[[problems]]\nid = "12.22"\n', encoding="utf-8")
    db = tmp_path / "hw.sqlite"
    graded = _lagrade("grade", str(subs), "-a", str(hw), "--db", str(db), "-j", "1", "--no-progress")
    assert graded.returncode == 0, graded.stderr[-2000:]
    _printable(graded.stdout + graded.stderr)
    assert "\\x1b]52;c;" in graded.stdout and MARKUP in graded.stdout, graded.stdout  # the summary's mistakes
    report = _lagrade("report", str(db))
    assert report.returncode == 0, report.stderr[-2000:]
    _printable(report.stdout + report.stderr)
    assert "\\x1b]52;c;" in report.stdout and MARKUP in report.stdout, report.stdout
    # the gradebook keeps what the student's file said, untouched
    import sqlite3

    con = sqlite3.connect(db)
    reasons = [r for (r,) in con.execute("SELECT reason FROM submissions WHERE student = 'ann'")]
    con.close()
    assert "\x1b]52;c;" in reasons[0]


def test_a_library_result_prints_printable():
    """``print(result)`` renders as ``lagrade check`` does: the same boundary."""
    from lagrade.verdicts.result import CheckResult, PartResult

    part = PartResult(part="L", verdict="invalid", score=0, max_score=1, method="exact", feedback=PAYLOAD,
                      read_as_text=PAYLOAD)
    text = str(CheckResult(problem="12.22", score=0, max_score=1, parts=[part], problems=[PAYLOAD]))
    _printable(text)
    assert text.count("\\x1b]52;c;") >= 2

