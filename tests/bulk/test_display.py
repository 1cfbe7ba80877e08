"""How an answer is shown in the gradebook: exactly ``str`` as text; sympy's presentation MathML, with
coordinates written q, q-dot and q-double-dot."""

from __future__ import annotations

import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st
from sympy.core.function import AppliedUndef
from sympy.printing.mathml import mathml

from lagrade.uses.bulk import display
from lagrade.uses.bulk.display import MATHML_MAX_CHARS, show

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from expression_strategies import expressions  # noqa: E402

t = sp.Symbol("t")
m1, l1, g = sp.symbols("m1 l1 g", positive=True)
th = sp.Function("theta1")(t)
THETA1 = "<msub><mi>&#952;</mi><mi>1</mi></msub>"


def _fresh(value):
    display._MATHML.clear()  # each example printed, not found whole in the caches (its parts may be,
    display._TEXT.clear()    # from earlier examples, as in a class)
    return show(value)


def _unkept(value, monkeypatch):
    """``value`` printed with no cache at all."""
    with monkeypatch.context() as m:
        m.setattr(display, "_compound", lambda *args: False)
        return _fresh(value)


def _well_formed(markup: str) -> None:
    # HTML's named entities (&InvisibleTimes;) are not XML's: the structure is what is checked
    ET.fromstring("<math>" + re.sub(r"&[A-Za-z]+;", "&#63;", markup) + "</math>")


SETTINGS = settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)


@SETTINGS
@given(expr=expressions)
def test_text_is_str(expr):
    text, _ = _fresh(expr)
    assert text == str(expr)[:MATHML_MAX_CHARS] + (" ..." if len(str(expr)) > MATHML_MAX_CHARS else "")


@SETTINGS
@given(value=st.one_of(st.lists(expressions, max_size=3), st.tuples(expressions),
                       st.dictionaries(st.sampled_from(["a", "omega_1"]), expressions, max_size=2),
                       st.dictionaries(expressions, st.booleans(), max_size=2)))
def test_text_of_containers_is_str(value):
    assert _fresh(value)[0] == str(value)[:MATHML_MAX_CHARS] + (" ..." if len(str(value)) > MATHML_MAX_CHARS else "")


@SETTINGS
@given(expr=expressions.filter(lambda e: not e.atoms(AppliedUndef)))
def test_mathml_without_coordinates_is_sympys(expr):
    text, markup = _fresh(expr)
    if len(text) <= MATHML_MAX_CHARS:
        assert markup == mathml(expr, printer="presentation")


@SETTINGS
@given(expr=expressions)
def test_mathml_is_well_formed_and_shows_no_coordinate_as_a_function_of_t(expr):
    text, markup = _fresh(expr)
    if len(text) > MATHML_MAX_CHARS:
        assert markup is None
        return
    _well_formed(markup)
    # q(t) is written q: sympy would print the function's name, then (t)
    for q in expr.atoms(AppliedUndef):
        assert f"<mi>{q.func.__name__}</mi><mrow><mo>(</mo>" not in markup


@pytest.mark.parametrize("expr, expected", [
    (th, THETA1),
    (th.diff(t), f'<mover accent="true">{THETA1}<mo>&#729;</mo></mover>'),
    (th.diff(t, 2), f'<mover accent="true">{THETA1}<mo>&#168;</mo></mover>'),
    # a dotted coordinate is one symbol to the reader: no brackets around it in a power
    (th.diff(t) ** 2, f'<msup><mover accent="true">{THETA1}<mo>&#729;</mo></mover><mn>2</mn></msup>'),
    (sp.cos(th), f"<mrow><mi>cos</mi><mrow><mo>(</mo>{THETA1}<mo>)</mo></mrow></mrow>"),
])
def test_coordinates_are_written_as_a_physicist_does(expr, expected):
    assert _fresh(expr)[1] == expected


def test_a_third_derivative_and_other_functions_stay_as_sympy_writes_them():
    third = _fresh(th.diff(t, 3))[1]
    assert "<mover" not in third and "<msup><mo>&dd;</mo><mn>3</mn></msup>" in third and THETA1 in third
    f = sp.Function("f")(t, g)  # a function of more than t is not a coordinate
    assert _fresh(f)[1] == mathml(f, printer="presentation")
    assert _fresh(sp.Derivative(f, g))[1] == mathml(sp.Derivative(f, g), printer="presentation")


def test_an_equation_of_motion_in_the_gradebook():
    eom = [sp.Eq(m1 * l1**2 * th.diff(t, 2), -m1 * g * l1 * sp.sin(th))]
    text, markup = _fresh(eom)
    assert text == str(eom)
    assert markup.startswith("<mrow><mo>[</mo>") and markup.count("<mo>=</mo>") == 1
    assert f'<mover accent="true">{THETA1}<mo>&#168;</mo></mover>' in markup
    assert f"<mi>sin</mi><mrow><mo>(</mo>{THETA1}<mo>)</mo></mrow>" in markup
    _well_formed(markup)


@pytest.mark.parametrize("value, text, markup", [
    (True, "True", "<mi>True</mi>"),
    ("a <b>", "a <b>", "<mtext>a &lt;b&gt;</mtext>"),
    (3, "3", "<mn>3</mn>"),
    ({"omega_1": sp.sqrt(g / l1)}, str({"omega_1": sp.sqrt(g / l1)}), None),
])
def test_plain_values(value, text, markup):
    shown = _fresh(value)
    assert shown[0] == text
    if markup is not None:
        assert shown[1] == markup
    else:
        _well_formed(shown[1])


def test_a_huge_answer_is_cut_and_gets_no_mathml():
    big = sum(sp.Symbol(f"x{i}") ** i for i in range(800))
    text, markup = _fresh(big)
    assert text.endswith(" ...") and len(text) == MATHML_MAX_CHARS + 4 and markup is None


def test_an_unprintable_value_is_shown_as_nothing():
    class Bad:
        def __str__(self):
            raise RuntimeError("no")
    assert _fresh(Bad()) == (None, None)


def test_the_same_text_is_rendered_once():
    first = _fresh(th.diff(t) ** 2)
    display._MATHML[("Pow", first[0])] = "cached"
    assert show(th.diff(t) ** 2) == (first[0], "cached")


@SETTINGS
@given(expr=expressions)
def test_a_value_equal_to_one_shown_before_gets_its_own_text(expr):
    """The text is kept by the value: an equal value built anew (as the next file's is) must print
    as str() prints it, whatever was shown before."""
    from lagrade.answer.jail.rebuild import rebuild_srepr

    huge = [f for f in expr.atoms(sp.Float) if f != 0 and not 1e-300 < abs(f) < 1e300]
    assume(not huge)
    _fresh(expr)
    again = rebuild_srepr(sp.srepr(expr))
    assert show(again)[0] == str(again)[:MATHML_MAX_CHARS] + (" ..." if len(str(again)) > MATHML_MAX_CHARS else "")
    assert show([again, again])[0] == str([again, again])[:MATHML_MAX_CHARS] + (" ..." if len(str([again] * 2)) > MATHML_MAX_CHARS else "")


def test_values_that_print_differently_are_not_one_key():
    x = sp.Symbol("x")
    _fresh(2 * x)
    assert show(sp.Float(2.0) * x)[0] == "2.0*x"
    assert show(sp.Float("1.5"))[0] == "1.50000000000000"
    assert show(sp.Float("1.5", 30))[0] == "1.50000000000000000000000000000"  # not equal to the one above
    assert show([2 * x])[0] == "[2*x]" and show((2 * x,))[0] == "(2*x,)"
    assert show(sp.Symbol("x", positive=True) * 2)[0] == "2*x"


def test_a_value_shown_again_is_not_printed_again(monkeypatch):
    first = _fresh(th.diff(t) ** 2 + m1 * g * l1)
    monkeypatch.setattr(display, "_text", lambda *a, **k: pytest.fail("printed again"))
    assert show(th.diff(t) ** 2 + m1 * g * l1) == first


def test_a_list_with_a_mutable_matrix_prints_as_str_also_once_the_matrix_has_changed():
    matrix = sp.Matrix([[1, m1]])
    value = [matrix, m1]
    assert _fresh(value)[0] == str(value) == "[Matrix([[1, m1]]), m1]"
    matrix[0, 0] = 2  # kept by its entries when shown, not by the object
    assert show(value)[0] == str(value) == "[Matrix([[2, m1]]), m1]"


@SETTINGS
@given(a=expressions.filter(lambda e: isinstance(e, sp.Expr)), b=expressions.filter(lambda e: isinstance(e, sp.Expr)))
def test_a_value_whose_parts_were_shown_before_prints_as_without_them(a, b):
    """Subexpressions are printed once per grader: a value made of parts shown before (an answer with
    one more term, an equation times a constant) prints as str() does, and as if nothing was kept."""
    for value in (a, b, [a, b]):
        _fresh(value)
    for value in (a + b, sp.Eq(a, 2 * b), [b, sp.sin(a)], {"x": a * b}):
        text, markup = _fresh(value)
        try:
            expected = str(value)
        except TypeError:  # sympy cannot print it (an ordering that compares NaN): shown as nothing
            expected = None
        if expected is None:
            assert text is None and markup is None
        else:
            assert text == expected[:MATHML_MAX_CHARS] + (" ..." if len(expected) > MATHML_MAX_CHARS else "")
        with pytest.MonkeyPatch.context() as mp:
            assert (text, markup) == _unkept(value, mp)


def test_a_float_prints_alone_at_full_precision_and_inside_without_trailing_zeros():
    x = sp.Symbol("x")
    half = sp.Float("1.5")
    display._PART_TEXT.clear()
    assert _fresh(x + half)[0] == "x + 1.5" and _fresh(sp.sin(x + half))[0] == "sin(x + 1.5)"
    assert _fresh(half)[0] == "1.50000000000000" and _fresh([half, x + half])[0] == "[1.50000000000000, x + 1.5]"


def test_a_part_is_printed_once(monkeypatch):
    x = sp.Symbol("x")
    inner = sp.cos(th) * m1 * g * l1
    _fresh(inner + x)
    monkeypatch.setattr(display._Text, "_print_Mul", lambda *a, **k: pytest.fail("printed again"))
    monkeypatch.setattr(display._PhysicsMathML, "_print_Mul", lambda *a, **k: pytest.fail("printed again"))
    assert _fresh(inner + x**2)[0] == str(inner + x**2)


def test_the_parts_kept_are_bounded_in_number_and_size(monkeypatch):
    for kept in (display._PART_TEXT, display._PART_MATHML):
        monkeypatch.setattr(kept, "entries", 5)
        kept.clear()
    x = sp.Symbol("x")
    for k in range(20):
        _fresh(sp.sin(x + k) * sp.cos(x - k))
    assert len(display._PART_TEXT) == len(display._PART_MATHML) == 5
    for kept in (display._PART_TEXT, display._PART_MATHML):
        monkeypatch.setattr(kept, "entries", 8192)
        monkeypatch.setattr(kept, "max_chars", 300)
    long = sp.Add(*(sp.Symbol(f"x_{k}") * sp.cos(sp.Symbol(f"y_{k}")) for k in range(40)))
    assert _fresh(sp.sin(long))[0] == str(sp.sin(long))
    for kept in (display._PART_TEXT, display._PART_MATHML):
        assert kept.chars == sum(map(len, kept.values())) <= 300 and kept
