"""The fast LaTeX reader (``reading/latex_subset.py``) against sympy's ANTLR parser.

Whatever the reader returns must be sympy's tree, node for node (``srepr``): on generated answers,
on token soup, on the grammar's odd corners and on the pre-pass output of every LaTeX answer we
have. Declining is always allowed (sympy then parses), so the last tests check that it does not
decline what answers are made of."""

from __future__ import annotations

from pathlib import Path

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

from lagrade.answer.reading import latex, latex_subset

ROOT = Path(__file__).resolve().parents[1]
CONVERTER = latex._antlr_converter()


def fast(text):
    return latex_subset.read(text, CONVERTER.sympy)


def sympys(text, retry: bool = True):
    """What lagrade used before the reader: ANTLR with SLL prediction, the full parser where SLL fails;
    None where sympy cannot parse the text.

    sympy itself is not deterministic on a zero denominator (``\\frac{0}{0}``): depending on its
    assumptions cache and the hash seed it may raise InconsistentAssumptions once and parse the same
    text after (measured: 2 of 2000 generated texts under PYTHONHASHSEED=1). So a refusal is
    confirmed once with sympy's cache cleared before it counts."""
    from sympy.parsing.latex import parse_latex

    try:
        return latex._parse_sll(text)
    except Exception:  # noqa: BLE001
        pass
    try:
        return parse_latex(text, strict=True)
    except Exception:  # noqa: BLE001
        if not retry:
            return None
    from sympy.core.cache import clear_cache

    clear_cache()
    return sympys(text, retry=False)


def assert_same_or_declined(text):
    ours = fast(text)
    if ours is None:
        return False
    theirs = sympys(text)
    assert theirs is not None, f"{text!r}: the reader read {sp.srepr(ours)}, sympy cannot parse it"
    assert sp.srepr(ours) == sp.srepr(theirs), f"{text!r}: {sp.srepr(ours)} != sympy's {sp.srepr(theirs)}"
    return True


# --------------------------------------------------------------------------- the grammar's corners

CORNERS = [
    r"\sin(x)^2", r"\sin(x) y", r"\sin (x)(y)", r"m(a+b)", r"\theta(t)", r"x(t)^2", r"e^x(t)",
    r"2 x 3", r"1 x 2", r"x 2 y", r"2 x", r"\frac12", r"\frac1{x}", r"\frac{1}{x}", r"\frac{x}{1}",
    r"\frac{\frac{1}{2}}{3}", r"\frac{a}{b}c", r"-a b", r"a - -b", r"--2", r"+x", r"-2", r"a - b + c",
    r"a/b/c", r"a \cdot b c", r"a \cdot -b", r"3 \times 4", r"a^b^c", r"a^{b}^{c}", r"x^\frac{1}{2}",
    r"\sin^{-1}(x)", r"\sin^2(x)", r"\cos^{2}(x)", r"\exp^2(x)", r"\ln(x)", r"\log(x)", r"\lg(x)",
    r"\arcsin(x)", r"\arsinh(x)", r"\sinh(x)", r"\sqrt[3]{x}", r"\sqrt{x+1}", r"0.5 m", r"2.25",
    r"\frac{1}{2} m v^2", r"x = y", r"x = x", r"1 = 2", r"(a)(b)", r"{a}b", r"[a]b", r"\mathit{ZQA} (b+c)",
    r"\pi r^2", r"-\frac{g}{l}\sin(\theta)", r"\cos ( \mathit{ZQJ}  -  \mathit{ZQK} )", r"1/2 x",
    r"a \left( b + c \right) k", r"a \, b", r"a\quad b",
]


@pytest.mark.parametrize("text", CORNERS)
def test_the_reader_builds_sympys_tree_in_the_grammars_corners(text):
    assert assert_same_or_declined(text), f"{text!r} was declined"


@pytest.mark.parametrize("text", [
    r"x^2 3",  # the number 23 to sympy
    r"\sin x", r"\sin 2x",  # an argument without parentheses
    r"x^-1", r"(", r"x^", r"()", r"a = b = c", r"x_1", r"x'", r"|x|", r"3!", r"\frac{d}{dt}(x)", r"d",
    r"\infty", r"\alpha_1", r"\left( a + b \right) c", r"a \quad", r"\mathit{Z Q}", r"\mathit{}", r"2.", r"1,000", r"a < b", r"\unknown x", r"é",
])
def test_the_reader_declines_what_it_does_not_know(text):
    assert fast(text) is None


# --------------------------------------------------------------------------- generated text

_NAMES = st.sampled_from(["x", "m", "g", "a", "k", "l", "e", r"\theta", r"\pi", r"\omega", r"\mathit{ZQA}",
                          r"\mathit{ZQBC}"])
_NUMBERS = st.sampled_from(["0", "1", "2", "12", "0.5", "3.25", "10"])
_JOINS = st.sampled_from([" + ", " - ", "-", "+", r" \cdot ", r"\times ", " / ", "*", " ", ""])


def _combine(children):
    return st.one_of(
        st.tuples(children, _JOINS, children).map("".join),
        children.map(lambda a: "-" + a),
        children.map(lambda a: f"({a})"),
        children.map(lambda a: f"{{{a}}}"),
        st.tuples(children, st.sampled_from(["2", "{2}", "{-1}", r"\frac{1}{2}", "x", "{a + b}", r"\theta"]))
        .map(lambda p: f"{p[0]}^{p[1]}"),
        st.tuples(children, children).map(lambda p: rf"\frac{{{p[0]}}}{{{p[1]}}}"),
        children.map(lambda a: rf"\sqrt{{{a}}}"),
        st.tuples(st.sampled_from([r"\sin", r"\cos", r"\sin^2", r"\cos^{-1}", r"\tan^{2}", r"\ln", r"\exp",
                                   r"\tanh", r"\arctan", r"\lg", r"\log"]), children)
        .map(lambda p: f"{p[0]}({p[1]})"),
        st.tuples(st.sampled_from(["f", "m", r"\theta"]), children).map(lambda p: f"{p[0]}({p[1]})"),
    )


_EXPRESSIONS = st.recursive(st.one_of(_NAMES, _NUMBERS), _combine, max_leaves=8)
_ANSWERS = st.one_of(_EXPRESSIONS, st.tuples(_EXPRESSIONS, _EXPRESSIONS).map(lambda p: f"{p[0]} = {p[1]}"))
_SOUP = st.lists(st.sampled_from(["x", "2", "3", ".", "+", "-", "=", "(", ")", "{", "}", "[", "]", "^", "/",
                                  r"\cdot", r"\frac", r"\sqrt", r"\sin", r"\theta", r"\mathit{A}", "f", " "]),
                 min_size=1, max_size=12).map("".join)


@settings(max_examples=400, deadline=None, derandomize=True)
@given(text=_ANSWERS)
def test_the_reader_builds_sympys_tree_for_generated_answers(text):
    assert_same_or_declined(text)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(text=_SOUP)
def test_the_reader_accepts_no_text_sympy_refuses_and_reads_the_rest_as_sympy(text):
    assert_same_or_declined(text)


# --------------------------------------------------------------------------- what answers are made of

def _golden_latex_answers():
    return sorted(p for p in (ROOT / "tests" / "answers").glob("*/*.toml") if "\\" in p.read_text())


def test_the_reader_reads_every_golden_latex_answer_itself(monkeypatch):
    """Every item of every LaTeX answer we have goes through the reader, except the operator
    form d/dt(...) (a differential to sympy's grammar): sympy's parser is the fallback, not the rule."""
    from lagrade.answer.reading.load import load_answer
    from lagrade.problem.library import load_problem

    read, declined = [], []
    real_read = latex_subset.read

    def spy(text, module):
        tree = real_read(text, module)
        (read if tree is not None else declined).append(text)
        return tree

    monkeypatch.setattr(latex_subset, "read", spy)
    paths = _golden_latex_answers()
    assert len(paths) >= 10
    for path in paths:
        load_answer(path, load_problem(path.parent.name))
    assert len(read) >= 50
    assert [t for t in declined if r"\frac{d}{dt}" not in t] == []
    monkeypatch.setattr(latex_subset, "read", real_read)
    for text in read:
        assert_same_or_declined(text)


def test_an_answer_the_reader_reads_does_not_load_sympys_latex_parser(tmp_path):
    """Importing sympy's converter deserializes ANTLR's grammar (about 0.65 s of CPU, in every grader
    process and every `lagrade check` of a LaTeX answer): it must wait until the reader declines.
    A fresh interpreter, because this test session has imported it already."""
    import subprocess
    import sys

    answer = tmp_path / "12.22.toml"
    answer.write_text('L = "\\\\frac{1}{2} m_1 \\\\dot{x}^2 + m_1 g x"\n', encoding="utf-8")
    probe = (
        "import sys\n"
        "from lagrade.answer.reading.load import load_answer\n"
        "from lagrade.problem.library import load_problem\n"
        f"loaded = load_answer(__import__('pathlib').Path({str(answer)!r}), load_problem('12.22'))\n"
        "assert 'L' in loaded.values, loaded.problems\n"
        "print('sympy.parsing.latex._parse_latex_antlr' in sys.modules)\n"
    )
    out = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False"]
