"""Generating a class folder whose expected grades are known by construction, not by grading.

Sources: the hand-written reference solutions (full marks), the golden answers ``correct_*``
(full marks) and ``wrong_*`` (their ``# expect:`` verdicts; a ``partial`` part scores the share of
its equations/entries that are right, pinned in ``PARTIAL``), variants of the references made
equivalent by rewriting (full marks) or wrong by a rule the README documents, broken files and
hostile files (0, every part ``invalid`` or ``missing``, with a reason).
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
FAST_PROBLEMS = ["12.43", "12.3", "12.22", "ex12.3"]

#: the share of a ``partial`` part that is right, from how the golden file is wrong
PARTIAL = {
    ("12.43", "wrong_sign_of_V", "hamilton"): 1 / 2,   # theta' right, p_theta' wrong: 1 of 2 equations
    ("12.3", "wrong_forgets_second_spring_on_x1", "eom"): 1 / 2,  # the x1 equation wrong, x2 right
    ("12.22", "wrong_S3_equals_S1", "S_t"): 2 / 3,     # S1 and S2 right, S3 wrong
    ("ex12.3", "wrong_relative_acceleration", "a"): 1 / 3,  # m1 right; m2 and m3 wrong
}

#: appended to a reference solution: the same answer written differently (full marks)
EQUIVALENT = {
    "12.43": "from sympy import expand\nH = expand(H + 7*m*g*l)\nhamilton = [Eq(e.rhs, e.lhs) for e in hamilton]\n"
             "eom = Eq(l*theta.diff(t, 2) + g*sin(theta), 0)\n",
    "12.3": "from sympy import expand\nL = expand(L)\neom = [Eq(e.lhs - e.rhs, 0) for e in eom][::-1]\n",
    "12.22": "from sympy import expand, together\nL = expand(L) + 5*m1*g\neom = [Eq(2*(e.lhs - e.rhs), 0) for e in eom]\n"
             "a = {k: together(v) for k, v in a.items()}\n",
    "ex12.3": "from sympy import expand, cancel\nL = expand(L)\neom = list(reversed(eom))\n"
              "a = {k: cancel(v) for k, v in a.items()}\n",
    "12.14": "from sympy import expand\nL = expand(L) + 3*m2*g*l1\neom_exact = [Eq(e.lhs - e.rhs, 0) for e in eom_exact][::-1]\n"
             "omega = omega[::-1]\n",
}

#: appended to a reference solution: wrong by a documented rule -> (code, {part: fraction})
SCALED = {
    "12.43": ("H = 2*H\n", {"H": 0.0}),          # H - H_ref must depend on t at most
    "12.3": ("L = 3*L\n", {"L": 0.5}),            # c*L, c != 1: half the credit
    "12.22": ("L = 3*L\n", {"L": 0.5}),
    "ex12.3": ("L = 3*L\n", {"L": 0.5}),
    "12.14": ("L = 3*L\n", {"L": 0.5}),
}

BROKEN = {
    "syntax.py": b"from sympy import *\nL = (m*\n",
    "name_error.py": b"from sympy import *\nL = undefined_name + 1\n",
    "empty.py": b"",
    "not_utf8.py": b"L = 1\n# \xff\xfe\xfa\n",
    "bad.toml": b'L = "m*\n',
}


def hostile_sources(sentinel: str) -> dict[str, str]:
    """Files that attack the grader; ``sentinel`` is a path none of them may create."""
    s = repr(sentinel)
    ref = repr(str(REPO / "reference_solutions" / "12.43" / "answer.py"))
    return {
        "import_os.py": f"import os\nos.system('touch ' + {s})\n",
        "subprocess.py": f"import subprocess\nsubprocess.run(['touch', {s}])\nH = 1\n",
        "socket.py": "import socket\nsocket.create_connection(('1.1.1.1', 80))\nH = 1\n",
        "open_write.py": f"open({s}, 'w').write('pwned')\nH = 1\n",
        "open_read_reference.py": f"H = open({ref}).read()\n",
        "pathlib_read_reference.py": f"import pathlib\nH = pathlib.Path({ref}).read_text()\n",
        "pathlib_write.py": f"import pathlib\npathlib.Path({s}).write_text('pwned')\nH = 1\n",
        "subclasses.py": "x = ().__class__.__bases__[0].__subclasses__()\nH = len(x)\n",
        "subclasses_popen.py": "P = [c for c in object.__subclasses__() if c.__name__ == 'Popen'][0]\nP(['true'])\n",
        "builtins_escape.py": "b = __builtins__\nH = b['__import__']('os').getcwd()\n",
        "getattr_open.py": "f = getattr(__builtins__, 'op' + 'en')\nH = f('/etc/passwd').read()\n",
        "eval_exec.py": "exec(\"import os\\nos.system('true')\")\nH = eval('1+1')\n",
        "sympify_string.py": "from sympy import sympify\nH = sympify(\"__import__('os').system('true')\")\n",
        "frame_walk.py": "def f():\n    yield 1\ng = f()\nH = g.gi_frame.f_back\n",
        "while_true.py": "while True:\n    pass\n",
        "busy_sympy.py": "from sympy import *\nx = Symbol('x')\nwhile True:\n    e = expand((x + 1)**50)\n",
        "memory_bomb.py": "x = [1] * (10**10)\nH = 1\n",
        "memory_string.py": "s = 'a' * 10**11\nH = 1\n",
        "memory_grow.py": "x = []\nwhile True:\n    x.append(' ' * 10**6)\n",
        "huge_exponent.py": "n = 10**(10**9)\nH = n\n",
        "huge_power_tower.py": "from sympy import Integer\nH = Integer(9)**(Integer(9)**(Integer(9)**9))\n",
        "deep_recursion.py": "def f(n):\n    return f(n + 1)\nH = f(0)\n",
        "fork.py": "import os\nos.fork()\nH = 1\n",
        "multiprocessing.py": "import multiprocessing\nmultiprocessing.Process(target=print).start()\nH = 1\n",
        "ctypes.py": "import ctypes\nctypes.CDLL(None).system(b'true')\nH = 1\n",
        "exit.py": "raise SystemExit(0)\n",
        "junk_stdout.py": "for i in range(100000):\n    print('\\x1b[2J\\x00 junk {\"token\": 1} ' * 10)\n",
        "junk_stdout_flood.py": "print('x' * 50_000_000)\n",
        "signal_parent.py": "import signal, os\nos.kill(os.getppid(), signal.SIGKILL)\n",
        "class_def.py": "class A:\n    pass\nH = 1\n",
        "try_swallow.py": "try:\n    while True:\n        pass\nexcept BaseException:\n    H = 1\n",
        "lambda_globals.py": "f = lambda: 0\nH = f.__globals__\n",
        "sympy_preview.py": "from sympy import preview, Symbol\npreview(Symbol('x'), filename=" + s + ")\n",
    }


@dataclass(frozen=True)
class Variant:
    name: str
    suffix: str
    data: bytes
    #: part -> fraction of its weight expected; None: zero, every part invalid or missing, a reason
    expect: dict[str, float] | None


def _expect_line(text: str) -> dict[str, str]:
    m = re.search(r"^#\s*expect:\s*(.+)$", text, re.MULTILINE)
    out = {}
    for item in (m.group(1).split(",") if m else []):
        part, verdict = (x.strip() for x in item.split("=", 1))
        out[part] = verdict
    return out


def part_names(pid: str) -> list[str]:
    """The parts of a problem as its TOML file lists them (reading the spec, not grading)."""
    from lagrade.problem.library import load_problem

    return [p.name for p in load_problem(pid).parts]


def part_weights(pid: str) -> dict[str, float]:
    from lagrade.problem.library import load_problem

    return {p.name: p.weight for p in load_problem(pid).parts}


def variants(pid: str, sentinel: str, hostile: bool = True, broken: bool = True, share: tuple[int, int] = (0, 1),
             legit_repeat: int = 1) -> list[Variant]:
    """Every variant of ``pid``; hostile files ``i`` with ``i % share[1] == share[0]`` only."""
    parts = part_names(pid)
    full = {p: 1.0 for p in parts}
    ref = (REPO / "reference_solutions" / pid / "answer.py").read_text()
    out = [Variant("reference", ".py", ref.encode(), full),
           Variant("equivalent", ".py", (ref + "\n" + EQUIVALENT[pid]).encode(), full),
           Variant("junk_print_then_correct", ".py",
                   ("print('\\x1b[31m' + 'junk ' * 2000)\n" + ref).encode(), full)]
    code, wrong = SCALED[pid]
    out.append(Variant("scaled", ".py", (ref + "\n" + code).encode(), {**full, **wrong}))
    for f in sorted((REPO / "tests" / "answers" / pid).iterdir()):
        if f.suffix not in (".py", ".toml"):
            continue
        text = f.read_text()
        if f.stem.startswith("correct_"):
            out.append(Variant(f.stem, f.suffix, f.read_bytes(), full))
        elif f.stem.startswith("wrong_"):
            pinned = _expect_line(text)
            if set(pinned) != set(parts) or any(v == "partial" and (pid, f.stem, k) not in PARTIAL
                                                for k, v in pinned.items()):
                continue  # its score cannot be derived from the file: not used (new golden files land here)
            exp = {}
            for part, verdict in pinned.items():
                if verdict == "correct":
                    exp[part] = 1.0
                elif verdict == "partial":
                    exp[part] = PARTIAL[(pid, f.stem, part)]
                else:
                    exp[part] = 0.0
            out.append(Variant(f.stem, f.suffix, f.read_bytes(), exp))
    out = out * legit_repeat
    if broken:
        out += [Variant(f"broken_{n}", Path(n).suffix, data, None) for n, data in BROKEN.items()]
    if hostile:
        out += [Variant(f"hostile_{Path(n).stem}", ".py", src.encode(), None)
                for i, (n, src) in enumerate(hostile_sources(sentinel).items()) if i % share[1] == share[0]]
    return out


@dataclass(frozen=True)
class Expected:
    student: str
    problem: str
    variant: str
    expect: dict[str, float] | None

    def score(self, weights: dict[str, float]) -> float:
        """The file's score: its parts' shares, the extra parts (not asked by the book) left out, as the
        problem's total leaves them out."""
        if self.expect is None:
            return 0.0
        extra = extra_parts(self.problem)
        return sum(weights[p] * f for p, f in self.expect.items() if p not in extra)


def extra_parts(pid: str) -> set[str]:
    from lagrade.problem.library import load_problem

    return {p.name for p in load_problem(pid).parts if getattr(p, "extra", False)}


def make_class(root: Path, students: int, problems: list[str] = FAST_PROBLEMS, sentinel: str = "/nonexistent",
               hostile: bool = True, broken: bool = True, extras: bool = True) -> list[Expected]:
    """Write ``root/<student>/<pid>.<ext>``; every variant appears, then the pools cycle."""
    pools = {pid: variants(pid, sentinel, hostile, broken, (j, len(problems)), legit_repeat=3)
             for j, pid in enumerate(problems)}
    expected = []
    for i in range(students):
        student = f"s{i:03d}"
        d = root / student
        d.mkdir(parents=True, exist_ok=True)
        for j, pid in enumerate(problems):
            if (i + j) % 29 == 28:  # now and then a student hands nothing in for a problem
                continue
            pool = pools[pid]
            v = pool[(i * len(problems) + j * 7 + i // len(pool)) % len(pool)]
            (d / f"{pid}{v.suffix}").write_bytes(v.data)
            expected.append(Expected(student, pid, v.name, v.expect))
    if extras:
        (root / "README.md").write_text("instructions\n")
        (root / "s000" / "notes.txt").write_text("hello\n")
        (root / "s001" / "12.99.py").write_text("H = 1\n")
        (root / "s002" / "old").mkdir()
        (root / "s002" / "old" / f"{problems[0]}.py").write_text("H = 1\n")
        (root / ".hidden").mkdir()
        os.symlink(REPO / "reference_solutions" / problems[0] / "answer.py", root / "s003" / f"{problems[0]}_link.py")
        twin = root / "twin"
        twin.mkdir()
        (twin / f"{problems[0]}.py").write_text("H = 1\n")
        (twin / f"{problems[0]}.toml").write_text('H = "1"\n')
    return expected


EXPECTED_SKIPS = {  # path -> a word the reason must contain
    "README.md": "student folder",
    "s000/notes.txt": "not an answer file",
    "s001/12.99.py": "not in the assignment",
    "s002/old": "folder inside",
    ".hidden": "hidden",
}


def assignment_toml(problems: list[str] = FAST_PROBLEMS, *, name: str = "hw7", accuracy: str = "default",
                    cpu: float = 1, wall: float = 4, memory_mb: int = 300, weights: dict | None = None) -> str:
    lines = [f'name = "{name}"', 'title = "Homework 7"', f'accuracy = "{accuracy}"', "",
             "[limits]", f"cpu_seconds = {cpu}", f"wall_seconds = {wall}", f"memory_mb = {memory_mb}",
             "grading_seconds = 60", ""]
    for pid in problems:
        lines += ["[[problems]]", f'id = "{pid}"']
        if weights and pid in weights:
            lines.append(f"weight = {weights[pid]}")
        lines.append("")
    return "\n".join(lines)
