"""The sandbox must return honest values for good answers and contain hostile ones."""

from __future__ import annotations

import os
import sys
from pathlib import Path

import pytest
import sympy as sp

from lagrade.answer.jail import sandbox, zygote
from lagrade.answer.jail.rebuild import decode_value
from lagrade.answer.jail.sandbox import SandboxLimits, run_answer_file

# wall time is generous so that a busy test machine still hits the CPU limit first
FAST = SandboxLimits(cpu_seconds=2, wall_seconds=8, memory_mb=256)

t = sp.Symbol("t")
theta = sp.Function("theta")(t)
m, g, l = sp.symbols("m g l")

GOOD = """\
from lagrade.answer import *
theta = coordinates("theta")
m, g, l = parameters("m g l")
L = m*l**2*dot(theta)**2/2 + m*g*l*cos(theta)
eom = [Eq(m*l**2*dot(theta, 2) + m*g*l*sin(theta), 0)]
tensions = {"T": m*g*cos(theta) + m*l*dot(theta)**2, "N": 0}
cyclic = False
conserved = [True, False]
dof = 1
period = 2*pi*sqrt(l/g)
M = Matrix([[1, 2], [3, 4]])
print("some output")
"""


def write(tmp_path: Path, text: str, name: str = "answer.py") -> Path:
    path = tmp_path / name
    path.write_text(text)
    return path


def test_good_answer_round_trips(tmp_path):
    wanted = ["L", "eom", "tensions", "cyclic", "conserved", "dof", "period", "M", "absent"]
    out = run_answer_file(write(tmp_path, GOOD), wanted)
    assert out.status == "ok", out.problems
    assert out.problems == []
    assert "some output" in out.stdout
    got = {k: decode_value(v) for k, v in out.values.items()}
    assert set(got) == set(wanted) - {"absent"}
    assert got["L"] == m * l**2 * theta.diff(t) ** 2 / 2 + m * g * l * sp.cos(theta)
    assert got["eom"] == [sp.Eq(m * l**2 * theta.diff(t, 2) + m * g * l * sp.sin(theta), 0)]
    assert got["tensions"] == {"T": m * g * sp.cos(theta) + m * l * theta.diff(t) ** 2, "N": 0}
    assert got["cyclic"] is False and got["conserved"] == [True, False]
    assert got["dof"] == 1 and type(got["dof"]) is int
    assert got["period"] == 2 * sp.pi * sp.sqrt(l / g)
    assert got["M"] == [[1, 2], [3, 4]]


def test_non_expression_value_is_a_problem(tmp_path):
    out = run_answer_file(write(tmp_path, "def helper(x):\n    return x\nL = helper\nH = 1\n"), ["L", "H"])
    assert out.status == "ok"
    assert "L" not in out.values and decode_value(out.values["H"]) == 1
    assert len(out.problems) == 1 and "'L' is a function" in out.problems[0].message


def test_syntax_error_reports_its_line(tmp_path):
    out = run_answer_file(write(tmp_path, "x = 1\ny = 2 +\nz = 3\n"), ["x"])
    assert out.status == "error"
    assert len(out.problems) == 1
    assert out.problems[0].line == 2
    assert str(out.problems[0]).startswith("answer.py:2: syntax error")


def test_name_error_keeps_earlier_values(tmp_path):
    src = "from lagrade.answer import *\ntheta = coordinates('theta')\nL = dot(theta)**2\nH = thta + 1\n"
    out = run_answer_file(write(tmp_path, src), ["L", "H"])
    assert out.status == "error"
    assert [str(p) for p in out.problems] == ["answer.py:4: NameError: name 'thta' is not defined"]
    assert decode_value(out.values["L"]) == theta.diff(t) ** 2
    assert "H" not in out.values


def test_error_inside_helper_reports_answer_line(tmp_path):
    src = "def f(x):\n    return x / 0\n\nL = 1\nH = f(1)\n"
    out = run_answer_file(write(tmp_path, src), ["L"])
    assert out.status == "error" and out.problems[0].line == 2
    assert "ZeroDivisionError" in out.problems[0].message


# --------------------------------------------------------------------------- hostile corpus

CANARY_TEXT = "do not touch"

# (source, allowed statuses, fragment expected in the problems); PWN is replaced by a path the
# attack would create, CANARY by the canary file.
HOSTILE = {
    "import_os": ("import os\nos.system('touch PWN')", {"rejected"}, "import of 'os'"),
    "from_subprocess": ("from subprocess import run\nrun(['touch', 'PWN'])", {"rejected"}, "subprocess"),
    "dunder_import": ("__import__('os').system('touch PWN')", {"rejected"}, "__import__"),
    "subclasses": ("x = ().__class__.__bases__[0].__subclasses__()", {"rejected"}, "__class__"),
    "open_read": ("x = open('/etc/passwd').read()", {"rejected"}, "'open'"),
    "open_write": ("open('CANARY', 'w').write('pwned')", {"rejected"}, "'open'"),
    "getattr_sympify": ("import sympy\ngetattr(sympy, 'sympify')('1')", {"rejected"}, "getattr"),
    "sympify_payload": ("from sympy import *\nsympify(\"__import__('os').system('touch PWN')\")",
                        {"rejected"}, "sympify"),
    "S_string": ("from sympy import S\nx = S(\"__import__('os').system('touch PWN')\")", {"rejected"}, "S("),
    "lambdify_path": ("import sympy\nf = sympy.utilities.lambdify.lambdify(sympy.Symbol('x'), 1)",
                      {"rejected"}, "utilities"),
    "parsing_import": ("from sympy.parsing.sympy_parser import parse_expr", {"rejected"}, "sympy.parsing"),
    "preview_write": ("from sympy import *\npreview(Symbol('x'), viewer='file', filename='PWN')",
                      {"rejected"}, "preview"),
    "fork_via_sympy": ("import sympy\nsympy.core.cache.os.fork()", {"rejected"}, "os"),
    "frame_escape": ("g = (x for x in [1])\nf = g.gi_frame.f_back", {"rejected"}, "gi_frame"),
    "format_escape": ("s = '{0.__init__.__globals__}'.format(1)", {"rejected"}, "format"),
    "class_def": ("class A:\n    pass", {"rejected"}, "class"),
    "try_swallow": ("try:\n    pass\nexcept BaseException:\n    pass", {"rejected"}, "try"),
    "relative_import": ("from . import answer", {"rejected"}, "relative"),
    "infinite_loop": ("while True:\n    pass", {"timeout"}, "CPU time"),
    "huge_list": ("x = [0]*(10**10)", {"memory"}, "memory"),
    "huge_string": ("x = ' ' * 10**11", {"memory"}, "memory"),
    "huge_power": ("x = 10**10**10", {"timeout"}, "ran longer"),
    "deep_recursion": ("def f(n):\n    return f(n + 1)\n\nx = f(0)", {"error"}, "RecursionError"),
}


@pytest.fixture
def canary(tmp_path):
    box = tmp_path / "outside"
    box.mkdir()
    path = box / "canary.txt"
    path.write_text(CANARY_TEXT)
    return path


def _check_contained(canary: Path, before_cwd: set[str], pwn: Path) -> None:
    assert canary.read_text() == CANARY_TEXT
    assert sorted(p.name for p in canary.parent.iterdir()) == ["canary.txt"]
    assert set(os.listdir(".")) == before_cwd
    assert not pwn.exists()
    assert not Path("/tmp", pwn.name).exists()


@pytest.mark.parametrize("case", sorted(HOSTILE))
def test_hostile_answers_are_contained(case, tmp_path, canary):
    source, statuses, fragment = HOSTILE[case]
    pwn = tmp_path / f"pwned-{case}"
    source = source.replace("PWN", str(pwn)).replace("CANARY", str(canary))
    before = set(os.listdir("."))
    out = run_answer_file(write(tmp_path, source + "\nL = 1\n"), ["L", "x"], FAST)
    # what ended it is in the status and the message (a bound names itself: "ran longer than 8 s"), not in
    # seconds measured here, which a loaded machine stretches (issue 45); a hang is pytest-timeout's
    assert out.status in statuses, (out.status, out.problems)
    assert out.problems and all(p.file == "answer.py" for p in out.problems)
    assert any(fragment in str(p) for p in out.problems), out.problems
    _check_contained(canary, before, pwn)


def test_junk_on_stdout_does_not_break_the_result(tmp_path):
    out = run_answer_file(write(tmp_path, "print('x' * 10**7)\nprint('y' * 10**6)\nL = 5\n"), ["L"], FAST)
    assert out.status == "ok", out.problems
    assert decode_value(out.values["L"]) == 5
    assert 0 < len(out.stdout) <= 2100 and set(out.stdout.strip()) == {"x"}


def test_timeout_reports_loop_line(tmp_path):
    out = run_answer_file(write(tmp_path, "L = 1\nn = 0\nwhile True:\n    n += 1\n"), ["L"], FAST)
    assert out.status == "timeout"
    assert out.problems[0].line in (3, 4)
    assert "ran longer than 2 s of CPU time" in out.problems[0].message
    assert decode_value(out.values["L"]) == 1


def test_wall_clock_timeout_kills_the_child(tmp_path):
    # CPU-idle waiting cannot be written without imports, so use a slow sympy call with a short wall
    slow = "from sympy import *\nx = Symbol('x')\nL = 1\nfor i in range(10**9):\n    y = expand((x + i)**2)\n"
    out = run_answer_file(write(tmp_path, slow), ["L"], SandboxLimits(cpu_seconds=30, wall_seconds=1.5))
    # the wall bound, not the CPU bound (30 s: "ran longer than 30 s of CPU time"), ended it: the message
    # says which, where seconds measured here would depend on the machine's load (issue 45)
    assert out.status == "timeout" and out.problems[0].message.startswith("ran longer than 1.5 s ("), out.problems


# --------------------------------------------------------------------------- layers behind the screen
# With static screening switched off, the runtime layers alone must still hold.

FILEIO = (
    "B = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == '_IOBase'][0]\n"
    "R = [c for c in B.__subclasses__() if c.__name__ == '_RawIOBase'][0]\n"
    "F = [c for c in R.__subclasses__() if c.__name__ == 'FileIO'][0]\n"
)
RUNTIME = {
    "import_os": "import os\nos.system('touch PWN')",
    "builtin_open": "open('CANARY', 'w').write('pwned')",
    "subclass_system": (
        "w = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close'][0]\n"
        "w.__init__.__globals__['system']('touch PWN')"),
    "subclass_fork": (
        "w = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close'][0]\n"
        "w.__init__.__globals__['fork']()"),
    "subclass_fileio_write": FILEIO + "F('CANARY', 'w').write(b'pwned')",
    "subclass_fileio_read": FILEIO + "x = F('/etc/passwd').read()",
    "subclass_popen": (
        "import sympy\nP = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == 'Popen']\n"
        "P[0](['touch', 'PWN']) if P else sympy.printing.preview.preview(sympy.Symbol('x'), viewer='file', filename='PWN')"),
    "sympify_string": "import sympy\ncode = \"__import__('os').system('touch PWN')\"\nx = sympy.S(code)",
    "sympify_dunder_math": "import sympy\ncode = \"().__class__\"\nx = sympy.S(code)",
    "preview_file": "import sympy\nsympy.preview(sympy.Symbol('x'), viewer='file', filename='PWN', outputTexFile='PWN')",
    "lambdify": "import sympy\nf = sympy.lambdify(sympy.Symbol('y'), sympy.Symbol('y'))\nx = f(2)",
    "parse_expr": "from sympy.parsing.sympy_parser import parse_expr\nx = parse_expr(\"__import__('os').system('touch PWN')\")",
    "gc_objects": "import gc\nx = gc.get_objects()",
    "importlib": "import importlib\nimportlib.import_module('os').system('touch PWN')",
    "frames": "g = (x for x in [1])\nx = g.gi_frame.f_back.f_globals['os'].system('touch PWN')",
    "eval_builtin": "eval(\"__import__('os').system('touch PWN')\")",
}


@pytest.mark.parametrize("case", sorted(RUNTIME))
def test_runtime_layers_hold_without_screening(case, tmp_path, canary, monkeypatch):
    monkeypatch.setattr(sandbox, "screen_source", lambda source, filename: [])
    pwn = tmp_path / f"pwned-{case}"
    source = RUNTIME[case].replace("PWN", str(pwn)).replace("CANARY", str(canary))
    before = set(os.listdir("."))
    out = run_answer_file(write(tmp_path, "L = 1\n" + source + "\n"), ["L", "x"], FAST)
    assert out.status == "error", (out.status, out.problems)
    assert "x" not in out.values
    assert decode_value(out.values["L"]) == 1
    assert len(out.problems) == 1 and out.problems[0].line is not None and out.problems[0].line >= 2
    _check_contained(canary, before, pwn)


def test_child_cannot_forge_a_report(tmp_path, monkeypatch):
    """os.write is not audited, so an escaped answer could write to the result pipe; without the
    per-run token its report is refused."""
    monkeypatch.setattr(sandbox, "screen_source", lambda source, filename: [])
    fake = ('{"token": "0", "status": "ok", "problems": [], '
            '"values": {"L": {"kind": "expr", "srepr": "Integer(42)"}}}')
    src = ("w = [c for c in ().__class__.__base__.__subclasses__() if c.__name__ == '_wrap_close'][0]\n"
           f"w.__init__.__globals__['write'](3, b'{fake}')\n"
           "w.__init__.__globals__['_exit'](0)\n")
    out = run_answer_file(write(tmp_path, src), ["L"], FAST)
    assert out.status == "crashed" and out.values == {}


def test_oversized_file_is_rejected(tmp_path):
    out = run_answer_file(write(tmp_path, "x = 1\n" * 40_000), ["x"])
    assert out.status == "rejected" and "200 kB" in out.problems[0].message


def test_parent_is_still_healthy_after_hostile_runs(tmp_path):
    out = run_answer_file(write(tmp_path, "from lagrade.answer import *\nL = sin(t)\n"), ["L"])
    assert out.status == "ok" and decode_value(out.values["L"]) == sp.sin(t)
    assert os.getcwd() and sp.sympify("1 + 1") == 2


def test_the_child_sends_expressions_as_nodes_and_the_rest_as_srepr(tmp_path):
    src = ("from lagrade.answer import *\nth = Function('theta')(t)\n"
           "L = th.diff(t)**2/2 + cos(th)\nH = Heaviside(t)\nQ = [L, 2]\n")
    out = run_answer_file(write(tmp_path, src), ["L", "H", "Q"], FAST)
    assert out.status == "ok", out.problems
    assert out.values["L"].nodes is not None and out.values["L"].srepr is None
    assert out.values["H"].srepr is not None and out.values["H"].nodes is None  # no node form: srepr
    th = sp.Function("theta")(sp.Symbol("t"))
    assert decode_value(out.values["L"]) == th.diff(sp.Symbol("t")) ** 2 / 2 + sp.cos(th)
    assert decode_value(out.values["H"]) == sp.Heaviside(sp.Symbol("t"))
    assert decode_value(out.values["Q"])[0] == decode_value(out.values["L"])


def _open_fds() -> int:
    return len(os.listdir("/proc/self/fd"))


def test_an_answer_never_waited_for_or_cut_off_leaves_no_pipe_open(tmp_path, monkeypatch):
    """A grader process lives for a whole class: an answer started but never waited for (the grading
    stopped first) or whose reading a bound cut off must not keep the two pipes from its child open."""
    import gc

    path = write(tmp_path, GOOD)
    sandbox.run_answer_file(path, ["L"], FAST)  # the zygote and its pipes exist before counting
    before = _open_fds()
    for _ in range(5):
        sandbox.start_answer_file(path, ["L"], FAST)  # dropped at once
    gc.collect()
    assert _open_fds() == before

    def cut_off(*args, **kwargs):
        raise TimeoutError("the grading's bound")

    monkeypatch.setattr(sandbox, "_read", cut_off)
    running = sandbox.start_answer_file(path, ["L"], FAST)
    with pytest.raises(TimeoutError):
        running.wait()
    del running
    gc.collect()
    assert _open_fds() == before


def _install_paths() -> list[str]:
    """Where the grader's files are: Python, its packages, sympy, lagrade and the hidden references."""
    import sysconfig

    from lagrade.problem.library import reference_dir

    places = [sysconfig.get_paths()["stdlib"], sysconfig.get_paths()["purelib"], os.path.dirname(sp.__file__),
              str(reference_dir()), sys.prefix]
    return sorted({q for p in places for q in (p, os.path.realpath(p)) if len(Path(q).parts) > 2})


def test_a_warning_shows_the_answer_by_its_name_not_the_graders_path(tmp_path):
    """As shipped (the tripwires on): Python's own warning about the answer names it by its file
    name, never by the folder the grader keeps it in."""
    folder = tmp_path / "graders-private-folder"
    folder.mkdir()
    out = run_answer_file(write(folder, "L = 1\nif L is 1:\n    L = 2\n"), ["L"], FAST)
    assert out.status == "ok" and "answer.py:2: SyntaxWarning" in out.stdout, out
    assert str(folder) not in out.stdout and "graders-private-folder" not in out.stdout, out.stdout


def test_refusals_and_permission_denied_never_show_the_install_path(tmp_path, monkeypatch):
    """Issue 43, item 6: what the jail refuses (a write to sympy's own file, a read of the references)
    comes back to the student with the install locations replaced by neutral names; so does what
    the answer prints about them."""
    from lagrade.problem.library import reference_dir

    monkeypatch.setattr(sandbox, "TRIPWIRES", False)  # the OS jail's own refusals
    source = ("import os, sympy\nprint('sympy is in', os.path.dirname(sympy.__file__))\n"
              "try:\n    open(sympy.__file__, 'a')\nexcept OSError as exc:\n    print(exc)\n"
              f"L = open({str(reference_dir() / '12.22' / 'answer.py')!r}).read()\n")
    out = run_answer_file(write(tmp_path, source), ["L"], FAST)
    said = out.stdout + "\n".join(p.message for p in out.problems)
    assert out.status == "error" and "<hidden>/12.22/answer.py" in said and "<sympy>/__init__.py" in said, said
    leaked = [p for p in _install_paths() if p in said]
    assert not leaked, (leaked, said)


def test_neutral_paths_names_each_place():
    from lagrade.answer.jail.sandbox import neutral_paths
    from lagrade.problem.library import reference_dir

    sympy_dir = os.path.dirname(sp.__file__)
    text = f"{sympy_dir}/core/expr.py:1: UserWarning; {reference_dir()}/12.22/answer.py; /srv/class/bob/12.22.py:3"
    assert neutral_paths(text, "/srv/class/bob/12.22.py") == \
        "<sympy>/core/expr.py:1: UserWarning; <hidden>/12.22/answer.py; 12.22.py:3"
    assert neutral_paths("division by zero") == "division by zero"
