"""A value's key is equal only for the same value: what a grader keeps by it (a verdict, a text) must
never be handed to a value that is graded or shown differently."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings

from lagrade.answer.jail.rebuild import rebuild_srepr
from lagrade.answer.reading.value_key import value_key

sys.path.insert(0, str(Path(__file__).resolve().parent))
from expression_strategies import expressions  # noqa: E402

x = sp.Symbol("x")
t = sp.Symbol("t")
th = sp.Function("theta1")(t)

LOOK_ALIKES = [
    (sp.Integer(1), sp.Float(1.0)),
    (sp.Float("1.5"), sp.Float("1.5", 30)),
    (2 * x, 2 * sp.Symbol("x", positive=True)),
    (th, sp.Function("theta1", real=True)(t)),
    (x, "x"),
    (True, 1),
    (1, 1.0),
    (True, sp.true),
    (0.0, -0.0),
    ([x, 1], (x, 1)),
    ([x], [[x]]),
    ({"a": x, "b": 1}, {"b": 1, "a": x}),  # equal dicts, shown in another order
    ({x: 1}, {"x": 1}),
    (sp.Matrix([[1, x]]), sp.ImmutableMatrix([[1, x]])),
    (sp.Eq(th.diff(t, 2), -x * th), sp.Eq(-x * th, th.diff(t, 2))),
]


@pytest.mark.parametrize("a, b", LOOK_ALIKES, ids=[f"{a!r}-vs-{b!r}" for a, b in LOOK_ALIKES])
def test_values_graded_or_shown_differently_have_different_keys(a, b):
    assert value_key(a) is not None and value_key(b) is not None
    assert value_key(a) != value_key(b)
    assert len({value_key(a): "a", value_key(b): "b"}) == 2


@settings(max_examples=200, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)
@given(expr=expressions)
def test_an_equal_value_built_anew_has_the_same_key(expr):
    huge = [f for f in expr.atoms(sp.Float) if f != 0 and not 1e-300 < abs(f) < 1e300]
    assume(not huge)
    again = rebuild_srepr(sp.srepr(expr))
    for wrap in (lambda v: v, lambda v: [v, 1], lambda v: (v,), lambda v: {"omega": v, "ok": True}):
        assert value_key(wrap(again)) == value_key(wrap(expr))
        assert hash(value_key(wrap(again))) == hash(value_key(wrap(expr)))


def test_a_matrix_is_keyed_by_its_entries_when_asked():
    matrix = sp.Matrix([[1, x]])
    before = value_key(matrix)
    matrix[0, 0] = 2
    assert value_key(matrix) != before and value_key(matrix) == value_key(sp.Matrix([[2, x]]))


@pytest.mark.parametrize("value", [object(), [x, object()], {"a": {1, 2}}, {(x, object()): 1}])
def test_what_cannot_be_keyed_exactly_has_no_key(value):
    assert value_key(value) is None
