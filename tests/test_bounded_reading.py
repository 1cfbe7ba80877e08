"""Every cost of reading an answer is bounded before it is paid (issue 32, items 1, 2 and 4).

Each bomb goes through ``lagrade check`` as a student would hand it in, in a process of its own
bounded by a 60 s wall clock: it must end with a verdict (``--json``), no traceback, and exit code 1
(graded, not full marks) or 2 (the file gave nothing to grade). Before the readers estimated sizes,
the power bombs ran until killed (sympy computed 3**(2**30) while building the value, before any
bound started), the deep TOML died with a RecursionError (exit code 1, no grade) and the exotic
values were ``error`` verdicts.
"""

from __future__ import annotations

import json
import resource
import subprocess
import sys
import time

import pytest

from lagrade.problem.limits import (
    MAX_DEPTH,
    MAX_DERIVATIVE_TERMS,
    MAX_EXPANDED_TERMS,
    MAX_EXPONENT,
    MAX_POWER_DIGITS,
    MAX_TOML_DEPTH,
)

#: the wall-clock bound of every check here (the issue's "ends well within 60 s")
WALL = 60

HEAD = """from lagrade.answer import *
from sympy import Pow
m1, m2, m3, m4, g, l1, l2, l3, m = parameters("m1 m2 m3 m4 g l1 l2 l3 m")
x, y, z = coordinates("x y z")
"""


def _squarings(base: str, n: int, left: str = "(", right: str = ")^2") -> str:
    for _ in range(n):
        base = f"{left}{base}{right}"
    return base


BOMBS = {
    # item 1: powers of any base, nested powers, big integers, expansion
    "power_text.toml": (f'L = "{_squarings("3*g*x_d", 30)}"\n', {"L": "exponent too large"}),
    "power_py.py": (HEAD + "L = Pow(3*g*x.diff(t), 2**30, evaluate=False)\n", {"L": "exponent too large"}),
    "nested_powers_py.py": (HEAD + "L = Pow(Pow(3*g*x.diff(t), 2**15, evaluate=False), 2**15, evaluate=False)\n",
                            {"L": "exponent too large"}),
    "power_latex.toml": ('L = "' + _squarings(r"3 g \\dot{x}", 30, r"\\left(", r"\\right)^{2}") + '"\n',
                         {"L": "exponent too large"}),
    "number_power_py.py": (HEAD + "L = Pow(Integer(10)**50 * g, 1000, evaluate=False)\n", {"L": "number too large"}),
    "exponent_text.toml": ('L = "m1*x_d^1000000"\n', {"L": "exponent too large"}),
    "multinomial.toml": ('L = "(m1 + m2 + m3 + m4 + g + l1 + l2 + l3)^1000"\n', {"L": "multiplied out"}),
    "product.toml": ('L = "' + "*".join(f"(m1 + {i}*g)" for i in range(1, 31)) + '"\n', {"L": "multiplied out"}),
    "big_integer.py": (HEAD + "L = 10**5000\na = {'m1': 10**5000}\n",
                       {"L": "integer too large", "a": "integer too large"}),
    "derivative_text.toml": ('L = "diff(sin(x)*cos(y)*z^3*exp(x*y)*m1, t, 40)"\n', {"L": "derivative too large"}),
    "derivative_py.py": (HEAD + "L = Derivative(sin(x)*cos(y)*z**3*exp(x*y)*m1, (t, 40))\n",
                         {"L": "derivative too large"}),
    # item 2: nesting
    "unary_chain.toml": ('L = "' + "-" * 100_000 + 'x"\n', {"L": "nested too deeply"}),
    "brackets.toml": ('L = "' + "(" * 5000 + "x" + ")" * 5000 + '"\n', {"L": "nested too deeply"}),  # bounded before too
    # item 4: values no physical quantity takes, refused as invalid, never an `error`
    "exotic.py": (HEAD + "L = m1*x.diff(t)**2/2 + AccumBounds(-1, 1)*g\n"
                         "eom = [Max(x, y).diff(t, 2), 0, 0]\n"
                         "a = {'m1': O(x**3), 'm2': g, 'm3': g, 'm4': g}\n"
                         "S_t = {'S1': Integral(x, t), 'S2': g, 'S3': g}\n",
                  {"L": "AccumBounds", "eom": "DiracDelta", "a": "order term", "S_t": "Integral"}),
    "not_smooth.py": (HEAD + "L = m1*x.diff(t)**2/2 + Heaviside(x)*m1*g*x\n", {"L": "Heaviside is not differentiable"}),
}

#: files that give nothing to grade: exit code 2 with one line saying why, on every part
UNUSABLE = {
    "deep_toml.toml": ("eom = " + "[" * 60_000 + "]" * 60_000 + "\n", f"nested more than {MAX_TOML_DEPTH} levels"),
    "nine_levels.toml": ("eom = " + "[" * (MAX_TOML_DEPTH + 1) + '"x"' + "]" * (MAX_TOML_DEPTH + 1) + "\n",
                         f"nested more than {MAX_TOML_DEPTH} levels"),
}


def _children_cpu() -> float:
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def _check(path) -> tuple[int, dict, str, float]:
    """The check's exit code, result, stderr and CPU seconds: CPU, not the wall clock, which a loaded
    machine stretches (issue 45); the wall only ends a hang (``timeout``)."""
    start = _children_cpu()
    proc = subprocess.run([sys.executable, "-m", "lagrade", "check", "12.22", str(path), "--json"],
                          capture_output=True, text=True, timeout=WALL)
    seconds = _children_cpu() - start
    assert "Traceback" not in proc.stderr + proc.stdout, proc.stderr[-2000:]
    return proc.returncode, json.loads(proc.stdout), proc.stderr, seconds


@pytest.mark.parametrize("name", sorted(BOMBS))
def test_a_bomb_is_invalid_with_the_reason_within_the_wall_bound(tmp_path, name):
    text, expected = BOMBS[name]
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    code, result, _, seconds = _check(path)
    assert code == 1 and seconds < WALL
    verdicts = {p["part"]: p for p in result["parts"]}
    for part, reason in expected.items():
        assert verdicts[part]["verdict"] == "invalid", verdicts[part]
        assert reason in verdicts[part]["feedback"] and "\n" not in verdicts[part]["feedback"], verdicts[part]
    assert not any(p["verdict"] == "error" for p in result["parts"])


@pytest.mark.parametrize("name", sorted(UNUSABLE))
def test_a_file_nested_too_deeply_is_unusable_in_one_line(tmp_path, name):
    text, reason = UNUSABLE[name]
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    code, result, _, seconds = _check(path)
    assert code == 2 and seconds < WALL
    assert all(p["verdict"] == "invalid" and reason in p["feedback"] for p in result["parts"]), result["parts"]


def test_the_bounds_stated_are_the_bounds_applied():
    """Every refusal names the limit it applies, as docs/safety.md states it."""
    from lagrade.problem.notation import (
        RebuildError,
        TextAnswerError,
        check_derivative,
        check_expansion,
        check_power,
        parse_math,
    )

    import sympy as sp

    x = sp.Symbol("x")
    check_power(3 * x, MAX_EXPONENT)  # at the limit: built
    with pytest.raises(RebuildError, match=f"limit {MAX_EXPONENT}"):
        check_power(3 * x, MAX_EXPONENT + 1)
    with pytest.raises(RebuildError, match=f"limit {MAX_EXPONENT}"):
        check_power(x**40, 40)  # nested: 40 * 40 = 1600
    with pytest.raises(RebuildError, match=f"limit {MAX_POWER_DIGITS}"):
        check_power(sp.Integer(10**50) * x, 300)  # 15 000 digits
    with pytest.raises(RebuildError, match=f"limit {MAX_EXPANDED_TERMS}"):
        check_expansion([sp.Add(*sp.symbols("a:9")) ** 100])
    check_expansion(sp.Add(*sp.symbols("a:3")) ** 100)  # 5151 terms
    q = sp.Function("q")(sp.Symbol("t"))
    check_derivative(q, 2)
    check_derivative(x**2 * sp.sin(x) * sp.exp(x), 5)  # 8 nodes: 8**5 = 32768
    with pytest.raises(RebuildError, match=f"limit {MAX_DERIVATIVE_TERMS}"):
        check_derivative(x**2 * sp.sin(x) * sp.exp(x), 6)  # 8**6 = 262144
    with pytest.raises(TextAnswerError, match=f"more than {MAX_DEPTH} levels"):
        parse_math("(" * (MAX_DEPTH + 1) + "x" + ")" * (MAX_DEPTH + 1), ["x"])


def test_a_long_sum_in_text_is_not_nested():
    """Python's tree nests ``a + b + c`` one level a term: a sum of 300 terms was "nested too deeply"."""
    from lagrade.problem.notation import parse_math

    import sympy as sp

    value = parse_math(" + ".join(f"{i}*m*x_d^2" for i in range(1, 301)) + " - g/2/m*3", ["x"])
    m, g = sp.symbols("m g")
    xd = sp.Function("x")(sp.Symbol("t")).diff(sp.Symbol("t"))
    assert sp.simplify(value - (45150 * m * xd**2 - sp.Rational(3, 2) * g / m)) == 0


def test_reading_runs_under_the_grading_bound(tmp_path, monkeypatch):
    """Reading an answer's text (here made slow on purpose) is bounded by the CPU time of grading:
    the check ends with every part invalid, in about the bound, instead of reading for as long as it takes."""
    from lagrade.verdicts.grade import check
    from lagrade.answer.reading import load

    read = load._load_toml

    def slow(*args, **kwargs):
        end = time.process_time() + 20
        while time.process_time() < end:
            pass
        return read(*args, **kwargs)

    monkeypatch.setattr(load, "_load_toml", slow)
    path = tmp_path / "answer.toml"
    path.write_text('L = "m1*x_d^2/2"\n', encoding="utf-8")
    start = time.process_time()
    result = check("12.22", path, grading_seconds=1.0, read_as=())
    assert time.process_time() - start < 10
    assert all(p.verdict == "invalid" and "reading this answer took longer than 1 s" in p.feedback
               for p in result.parts), result.parts


def test_values_given_in_python_are_screened_alike():
    from lagrade.verdicts.grade import check

    import sympy as sp

    result = check("12.22", L=sp.AccumBounds(-1, 1), only=["L"], read_as=())
    assert result.parts[0].verdict == "invalid" and "AccumBounds" in result.parts[0].feedback
