"""Every `lagrade ...` line of README.md's command blocks, run as a user would, in a folder that has what
the line names (an answer file, an assignment, a class, a Canvas download): each ends with the exit code
the README's words imply (0, or 1 where an answer is graded short of full marks) and makes what it says.

Left to their own tests, said here so a new README line is not silently skipped: `pip ... && pytest`
(CI runs them), `lagrade serve` and `check --server` (a long-running server: tests/server),
`lagrade cache build` (every problem's references: tests/test_cache.py) and `lagrade bench accuracy`
(tests/test_bench_cli.py)."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
ELSEWHERE = ("pip ", "lagrade serve", "--server", "lagrade cache build", "lagrade bench ")


def readme_commands() -> list[str]:
    blocks = re.findall(r"```sh\n(.*?)```", (ROOT / "README.md").read_text(), re.S)
    lines = [re.split(r"\s#\s", line)[0].strip() for block in blocks for line in block.splitlines()]
    return [line for line in lines if line.startswith("lagrade ") and not any(s in line for s in ELSEWHERE)]


def _class(folder: Path) -> None:
    """hw7.toml (12.22), a class of two (bob right, eve wrong), a Canvas download, a credit file."""
    ref = (ROOT / "reference_solutions" / "12.22" / "answer.py").read_text()
    (folder / "hw7.toml").write_text('name = "hw7"\ntitle = "Homework 7"\n[[problems]]\nid = "12.22"\n')
    for student, text in (("bob", ref), ("eve", ref.replace("S_t = {", "S_t_wrong = {"))):
        (folder / "submissions" / student).mkdir(parents=True)
        (folder / "submissions" / student / "12.22.py").write_text(text)
    (folder / "canvas-download").mkdir()
    (folder / "canvas-download" / "lovelaceada_101_9001_12.22.py").write_text(ref)
    (folder / "credit.toml").write_text("scaled_lagrangian = 0.25\n")


@pytest.mark.slow
@pytest.mark.timeout(900)
def test_every_readme_command_runs_as_it_says(tmp_path):
    _class(tmp_path)
    lagrade = [sys.executable, "-m", "lagrade"]
    ran, failed = [], []
    for line in readme_commands():
        words = shlex.split(line)
        out_file = None
        if ">" in words:
            at = words.index(">")
            words, out_file = words[:at], tmp_path / words[at + 1]
        # the answer each check line grades: 12.22's reference, and a wrong 12.14 for the picture
        if words[1] == "check":
            source = ROOT / ("tests/answers/12.14/wrong_V_upper_mass_only.py" if words[2] == "12.14"
                             else "reference_solutions/12.22/answer.py")
            (tmp_path / "answer.py").write_text(source.read_text())
        if words[1] == "import":  # the import writes the class folder afresh
            words = [w if w != "submissions/" else "imported/" for w in words]
        res = subprocess.run([*lagrade, *words[1:]], cwd=tmp_path, capture_output=True, text=True, timeout=600,
                             env={**os.environ, "LAGRADE_NO_PROGRESS": "1"})
        if out_file is not None:
            out_file.write_text(res.stdout)
        ran.append(line)
        wrong_ok = words[1] in ("check",) and words[2] == "12.14"  # graded short of full marks: exit 1
        if res.returncode not in ((0, 1) if wrong_ok else (0,)):
            failed.append(f"{line}: exit {res.returncode}\n{res.stderr[-600:] or res.stdout[-600:]}")
    assert len(ran) >= 20 and not failed, "\n\n".join(failed)
    # what the lines say they make
    assert (tmp_path / "answer.py").is_file() and (tmp_path / "out.png").stat().st_size > 1000
    assert (tmp_path / "hw7.sqlite").is_file() and (tmp_path / "report" / "index.html").is_file()
    assert "bob" in (tmp_path / "hw7-canvas.csv").read_text() or (tmp_path / "hw7-canvas.csv").stat().st_size > 0
    assert (tmp_path / "autograder.zip").is_file() and (tmp_path / "pl" / "image" / "Dockerfile").is_file()
    assert any((tmp_path / "imported").iterdir())
