"""Every fenced example of README.md and docs/*.md, found by reading the markdown (a new block is picked up
without editing this file) and run or validated by the kind it is: Python blocks executed, answer blocks
(answer.py / answer.toml) graded, TOML problem, part, assignment and LTI snippets validated by the pydantic
models the loaders use, quoted JSON output checked against the result model, and every shell line's
`lagrade ...` parsed by the CLI (the README's lines are also run end to end: tests/test_readme_examples.py).

A block that cannot run in a test says so in the markdown, on the line before it:
`<!-- not run: reason -->`; the list of such blocks stays short and every entry has a reason."""

from __future__ import annotations

import json
import re
import shlex
import tomllib
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
BLOCK = re.compile(r"(?:<!--\s*not run:(?P<why>[^>]*)-->\s*\n)?[ ]*```(?P<lang>\w*)\n(?P<body>.*?)```", re.S)
MAX_NOT_RUN = 6


@dataclass(frozen=True)
class Block:
    file: str
    line: int
    lang: str
    body: str
    not_run: str | None

    def __str__(self) -> str:
        return f"{self.file}:{self.line}"


def blocks() -> list[Block]:
    found = []
    for path in DOCS:
        text = path.read_text()
        for m in BLOCK.finditer(text):
            # a block indented under a list item: drop the common indentation
            lines = m.group("body").splitlines()
            indent = min((len(x) - len(x.lstrip(" ")) for x in lines if x.strip()), default=0)
            body = "\n".join(x[indent:] for x in lines)
            line = text[: m.start("lang")].count("\n") + 1
            why = m.group("why").strip() if m.group("why") is not None else None
            found.append(Block(str(path.relative_to(ROOT)), line, m.group("lang"), body, why))
    return found


ALL = blocks()
RUN = [b for b in ALL if b.not_run is None]


def of(lang: str) -> list[Block]:
    return [b for b in RUN if b.lang == lang]


def test_every_block_is_run_or_says_why_not():
    assert len(ALL) >= 30, len(ALL)
    known = {"python", "toml", "json", "sh", ""}
    assert [str(b) for b in RUN if b.lang not in known] == []
    skipped = [b for b in ALL if b.not_run is not None]
    assert len(skipped) <= MAX_NOT_RUN, [str(b) for b in skipped]
    assert all(len(b.not_run) >= 15 for b in skipped), [(str(b), b.not_run) for b in skipped]


# --- Python ----------------------------------------------------------------------------------------------

def _is_answer(body: str) -> bool:
    return "lagrade.check" not in body and re.search(r"^(L|H|eom|hamilton) = ", body, re.M) is not None


@pytest.mark.parametrize("block", [b for b in of("python") if _is_answer(b.body)], ids=str)
def test_an_answer_py_block_earns_full_marks(block, tmp_path):
    import lagrade

    (tmp_path / "answer.py").write_text(block.body)
    result = lagrade.check("12.43", tmp_path / "answer.py")
    assert result.score == result.max_score, [(p.part, p.verdict, p.feedback) for p in result.parts]


@pytest.mark.slow
@pytest.mark.parametrize("block", [b for b in of("python") if not _is_answer(b.body)], ids=str)
def test_a_python_block_runs(block, tmp_path, monkeypatch):
    """The API blocks, executed as written, in a folder whose answer.py is 12.22's reference."""
    (tmp_path / "answer.py").write_text((ROOT / "reference_solutions" / "12.22" / "answer.py").read_text())
    monkeypatch.chdir(tmp_path)
    scope: dict = {}
    exec(compile(block.body, str(block), "exec"), scope)  # noqa: S102 - the docs' own example
    assert "result" not in scope or scope["result"].max_score > 0


# --- TOML ------------------------------------------------------------------------------------------------

def _toml(block: Block) -> dict:
    return tomllib.loads(block.body)


def _answer_toml(data: dict) -> bool:
    """Top-level formulas only: strings, or lists of strings, under part names."""
    def formula(v) -> bool:
        return isinstance(v, str) or (isinstance(v, list) and all(isinstance(x, str) for x in v))
    return bool(data) and all(formula(v) for v in data.values()) and not {"name", "id", "url"} & set(data)


@pytest.mark.parametrize("block", of("toml"), ids=str)
def test_a_toml_block_is_valid(block):
    """Parsed, then validated by the model that reads it (answer blocks are graded in the next test)."""
    from lagrade.uses.bulk.assignment import Assignment
    from lagrade.uses.server.lti import LtiConfig
    from lagrade.problem.spec import GeneralFunction, Part, Problem

    data = _toml(block)
    if _answer_toml(data):
        return
    if "id" in data and "parts" in data:
        Problem.model_validate(data)
    elif "platform" in data:
        LtiConfig.model_validate(data)
    elif "problems" in data or "gradescope" in data:  # an assignment, or a table of one
        Assignment.model_validate({"name": "hw7", "problems": [{"id": "12.22"}], **data})
    elif "systems" in data:  # a piece of a system: its functions, coordinates or constraints
        from lagrade.problem.spec import Constraint, Coordinate

        pieces = {"functions": GeneralFunction, "coordinates": Coordinate, "constraints": Constraint}
        assert set(data["systems"]) <= set(pieces), f"{block}: no model reads {sorted(data['systems'])}"
        for key, model in pieces.items():
            for piece in data["systems"].get(key, []):
                model.model_validate(piece)
    else:
        assert "parts" in data, f"{block}: no model reads this block"
        for part in data["parts"]:
            Part.model_validate(part)


@pytest.mark.parametrize("block", [b for b in of("toml") if _answer_toml(_toml(b))], ids=str)
def test_an_answer_toml_block_earns_full_marks(block, tmp_path):
    import lagrade

    (tmp_path / "answer.toml").write_text(block.body)
    result = lagrade.check("12.43", tmp_path / "answer.toml")
    assert result.score == result.max_score, [(p.part, p.verdict, p.feedback) for p in result.parts]


# --- quoted output ---------------------------------------------------------------------------------------

@pytest.mark.parametrize("block", of("json"), ids=str)
def test_quoted_json_names_the_result_fields(block):
    """The quoted `--json` output is abridged ("..."); its keys are the model's."""
    from lagrade.verdicts.result import CheckResult, PartResult

    keys = set(re.findall(r'"(\w+)":', block.body))
    top = {"problem", "score", "max_score", "parts", "problems"}
    assert top <= set(CheckResult.model_fields)
    assert keys - top <= set(PartResult.model_fields), keys - top - set(PartResult.model_fields)
    assert json.loads(block.body.replace(", ...", "").replace("...", "")) is not None


@pytest.mark.parametrize("block", of(""), ids=str)
def test_a_quoted_message_is_said_by_the_code(block):
    """A quoted one-line message: its fixed words appear in the source that prints it."""
    source = "\n".join(p.read_text() for p in (ROOT / "src" / "lagrade").rglob("*.py"))
    for line in block.body.splitlines():
        fixed = [w for w in re.split(r"\{[^}]*\}|hw7\.sqlite|\([^)]*\)", line.removeprefix("lagrade: ")) if w]
        for words in fixed:
            assert words.strip(" ;") in source, f"{block}: {words!r}"


# --- shell -----------------------------------------------------------------------------------------------

def shell_lines(block: Block) -> list[str]:
    out = []
    for raw in block.body.splitlines():
        line = re.split(r"\s#\s", raw)[0].strip()
        if line:
            out.append(line)
    return out


SHELL = [(b, line) for b in of("sh") for line in shell_lines(b)]


def _parse_lagrade(words: list[str]) -> None:
    """Resolve the subcommand (and a sub-subcommand) and let click parse its options, running nothing."""
    import click

    from lagrade.cli import main

    ctx = main.make_context("lagrade", list(words), resilient_parsing=False)
    command, args = main, list(words)
    while isinstance(command, click.Group):
        name, command, args = command.resolve_command(ctx, args)
        with command.make_context(name, list(args), parent=ctx) as ctx:  # raises on an unknown option
            pass
        args = ctx.protected_args + ctx.args if isinstance(command, click.Group) else []


@pytest.mark.parametrize("block, line", SHELL, ids=[f"{b}:{i}" for i, (b, _) in enumerate(SHELL)])
def test_a_shell_line_is_a_real_command(block, line, tmp_path, monkeypatch):
    """`lagrade` lines parse with the CLI (in a folder holding the files they name, empty); scripts and
    test paths they name exist; pip names an extra pyproject.toml has."""
    monkeypatch.chdir(tmp_path)
    words = shlex.split(line.split(" > ")[0].replace("[", " ").replace("]", " ")
                        if line.startswith(("python benchmarks",)) else line.split(" > ")[0])
    words = words[words.index("&&") + 1:] if "&&" in words else words
    if words[0].startswith("LAGRADE_"):
        words = words[1:]
    if words[0] == "lagrade":
        for word in words[2:]:
            if word.endswith("/") and not word.startswith(("http", "-")):
                (tmp_path / word).mkdir(parents=True, exist_ok=True)
            elif re.fullmatch(r"[\w.-]+\.(toml|py|csv|zip|sqlite)", word):
                (tmp_path / word).touch()
        _parse_lagrade(words[1:])
    elif words[0] == "python" and words[1] == "-c":
        pass  # run below
    elif words[0] == "python":
        assert (ROOT / words[1]).is_file(), line
    elif words[0] == "pytest":
        paths = [w for w in words[1:] if w.startswith("tests")]
        assert all((ROOT / p).exists() for p in paths), line
    elif words[0] == "pip":
        extras = re.findall(r"\[(\w+)\]", line)
        optional = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["optional-dependencies"]
        assert all(e in optional for e in extras), line
    else:
        pytest.fail(f"{block}: {line}: no runner for {words[0]!r}")


@pytest.mark.parametrize("line", [line for _, line in SHELL if line.startswith("python -c")])
def test_a_python_c_line_runs(line):
    import subprocess
    import sys

    code = shlex.split(line)[2]
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert res.returncode == 0 and res.stdout.strip(), res.stderr


def test_the_reader_sees_a_not_run_marker_and_an_indented_block():
    """The guard of the skip list: a marker on the line before a block (indented under a list item too)."""
    text = "1. a\n\n   <!-- not run: needs a real registry account -->\n   ```sh\n   docker login\n   ```\n"
    m = BLOCK.search(text)
    assert m.group("why").strip() == "needs a real registry account" and m.group("body").strip() == "docker login"
    assert any(b.not_run and "Docker Hub" in b.not_run for b in ALL)


@pytest.mark.parametrize("block", [b for b in of("json") if '"problem": "12.22"' in b.body], ids=str)
def test_quoted_json_main_lines_are_what_check_prints(block):
    """The quoted output's fixed lines against 12.22's reference graded now: the top-level keys in order,
    and the first part's name, verdict, evidence and the feedback's opening words (the rest is elided)."""
    import lagrade

    got = json.loads(lagrade.check("12.22", ROOT / "reference_solutions" / "12.22" / "answer.py").model_dump_json())
    assert list(got) == list(dict.fromkeys(re.findall(r'"(problem|score|max_score|parts|problems)":', block.body)))
    first = got["parts"][0]
    for key in ("part", "verdict", "method"):
        assert f'"{key}": "{first[key]}"' in block.body, (key, first[key])
    quoted = re.search(r'"feedback": "(.*?) \.\.\."', block.body).group(1)
    assert first["feedback"].startswith(quoted), (quoted, first["feedback"])
