"""rebuild_srepr must reproduce sympy's srepr faithfully and refuse everything else, quickly."""

from __future__ import annotations

import json
import time

import pytest
import sympy as sp
from hypothesis import HealthCheck, assume, given, settings

from expression_strategies import expressions
from lagrade.answer.jail.rebuild import (
    MAX_NODES,
    EncodedValue,
    RebuildError,
    decode_value,
    expr_nodes,
    rebuild_nodes,
    rebuild_srepr,
    srepr_text,
)

t = sp.Symbol("t")

# --------------------------------------------------------------------------- round trips

PRINTERS = pytest.mark.parametrize("printer", [sp.srepr, srepr_text], ids=["srepr", "srepr_text"])


@PRINTERS
@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)
@given(expr=expressions)
def test_round_trip_property(printer, expr):
    text = printer(expr)
    huge = [f for f in expr.atoms(sp.Float) if f != 0 and not 1e-300 < abs(f) < 1e300]
    assume(not huge)  # floats beyond double range are refused by design (see test_rejects_*)
    assert rebuild_srepr(text) == expr


#: sympy values of every kind an answer may hold
EXAMPLES = [
    sp.Function("theta")(t).diff(t, 2),
    sp.Eq(sp.Symbol("m", positive=True) * sp.Function("x")(t).diff(t) ** 2 / 2, sp.S.Half),
    sp.Rational(3, 7) * sp.pi + sp.E + sp.I,
    sp.Float("1.5"), sp.Float("1.5", 30), sp.Float("1e-400"), sp.oo, -sp.oo, sp.zoo, sp.nan,
    sp.true, sp.false, sp.ImmutableMatrix([[1, 2], [3, sp.Symbol("a")]]),
    sp.Piecewise((1, t > 0), (0, True)), sp.Tuple(1, 2), sp.Integral(sp.sin(t), (t, 0, 1)),
    sp.Lt(t, 1), sp.Ne(t, 1), sp.Ge(t, 2), sp.atan2(t, 1), sp.Max(t, 1), sp.Min(t, 2),
    sp.Heaviside(t), sp.DiracDelta(t), sp.floor(t), sp.ceiling(t), sp.re(t), sp.im(t),
    sp.Subs(sp.Function("f")(t).diff(t), t, 0), sp.Function("f")(t, sp.Symbol("m")),
    sp.EulerGamma, sp.Symbol("x", commutative=False), sp.series(sp.sin(t), t, 0, 4),
    sp.FiniteSet(1, t), sp.S.EmptySet, sp.And(t > 0, t < 1),
]


@pytest.mark.parametrize("expr", EXAMPLES)
@PRINTERS
def test_round_trip_examples(printer, expr):
    assert rebuild_srepr(printer(expr)) == expr


def test_python_containers_and_dummy():
    a, b = sp.symbols("a b")
    assert rebuild_srepr(sp.srepr((a, b))) == (a, b)
    assert rebuild_srepr(sp.srepr([a, 1])) == [a, 1]
    assert rebuild_srepr(sp.srepr({a: b})) == {a: b}
    assert rebuild_srepr(sp.srepr(sp.Dummy("z"))) == sp.Symbol("z")  # identity cannot cross processes
    assert rebuild_srepr("Half()") == sp.S.Half and rebuild_srepr("Pi()") == sp.pi
    assert rebuild_srepr("NegativeInfinity()") == -sp.oo and rebuild_srepr("ImaginaryUnit()") == sp.I


# --------------------------------------------------------------------------- refusals

@pytest.mark.parametrize("text, fragment", [
    ("__import__('os').system('echo hi')", "attribute"),
    ("__import__('os')", "unknown constructor"),
    ("Symbol('x').__class__", "attribute"),
    ("Integer(1).__class__.__bases__", "attribute"),
    ("(lambda: 1)()", "plain constructor"),
    ("lambda: 1", "unsupported syntax"),
    ("eval('1')", "unknown constructor"),
    ("sympify('x')", "unknown constructor"),
    ("Basic()", "unknown constructor"),
    ("Symbol('x; import os')", "invalid symbol name"),
    ("Symbol('" + "a" * 65 + "')", "invalid symbol name"),
    ("Function('f(x)')(Symbol('t'))", "invalid function name"),
    ("Symbol('x', commutative='yes')", "keyword"),
    ("Symbol('x', evil=True)", "unsupported symbol option"),
    ("Add(Symbol('x'), 'y')", "string arguments"),
    ("Integer('1')", "integer literal"),
    ("Integer(" + "9" * 61 + ")", "too large"),
    ("Float('1e999999999', precision=53)", "malformed Float"),
    ("Float('1.0', precision=1000000000)", "precision"),
    ("Pow(Integer(10), Pow(Integer(10), Integer(10)))", "number too large"),
    ("Pow(Integer(2), Integer(1000000000000000000000000000000000000000000000000000000000000))", "number too large"),
    ("Pow(Add(Integer(1), I), Integer(100000000000000000000000000000000000000000000000000))", "exponent too large"),
    ("Pow(Integer(2), Rational(1, 100000000000000000000000000000000000000000000000000))", "denominator"),
    ("Derivative(Function('f')(Symbol('t')), Tuple(Symbol('t'), Integer(1000000000)))", "derivative order"),
    ("x", "unknown name"),
    ("Symbol('x')[0]", "unsupported syntax"),
    ("[x for x in (1,)]", "unsupported syntax"),
    ("Add(*[Integer(1)])", "'*' arguments"),
    ("Add(**{})", "'**' arguments"),
    ("Symbol('x') + Symbol('y')", "unsupported syntax"),
    ("Integer(2**10)", "unsupported syntax"),
    ("", "not well formed"),
])
def test_rejections(text, fragment):
    start = time.process_time()
    with pytest.raises(RebuildError, match=None) as info:
        rebuild_srepr(text)
    assert fragment in str(info.value), str(info.value)
    assert time.process_time() - start < 1


def test_nested_exponent_tower_is_fast():
    text = "Pow(Integer(10), " * 50 + "Integer(10)" + ")" * 50
    start = time.process_time()
    with pytest.raises(RebuildError):
        rebuild_srepr(text)
    assert time.process_time() - start < 1


def test_many_big_integer_products_are_bounded():
    text = "Mul(" + ", ".join(["Integer(" + "9" * 60 + ")"] * 5000) + ")"
    with pytest.raises(RebuildError, match="too many digits"):
        rebuild_srepr(text)


@pytest.mark.parametrize("depth", [150, 5000, 100_000])
def test_deep_nesting_is_a_clear_error(depth):
    text = "sin(" * depth + "Symbol('x')" + ")" * depth
    with pytest.raises(RebuildError, match="nested too deeply"):
        rebuild_srepr(text)


def test_text_size_limit():
    with pytest.raises(RebuildError, match="too long"):
        rebuild_srepr("Integer(1)" + " " * 1_000_001)


def test_node_count_limit():
    text = "(" + ",".join(["pi"] * 200_000) + ")"
    with pytest.raises(RebuildError, match="too large"):
        rebuild_srepr(text)


def test_moderate_depth_is_fine():
    expr = sp.Symbol("x")
    for _ in range(40):
        expr = sp.sin(expr)
    assert rebuild_srepr(sp.srepr(expr)) == expr


# --------------------------------------------------------------------------- decode_value

def test_decode_value_nested():
    x = sp.Symbol("x")
    v = EncodedValue.model_validate({"kind": "dict", "items": [
        [{"kind": "str", "value": "a"}, {"kind": "list", "items": [
            {"kind": "expr", "srepr": sp.srepr(x**2)}, {"kind": "bool", "value": True},
            {"kind": "int", "value": 3}, {"kind": "float", "value": 0.5}]}],
        [{"kind": "expr", "srepr": "Symbol('x')"}, {"kind": "dict", "items": []}],
    ]})
    assert decode_value(v) == {"a": [x**2, True, 3, 0.5], x: {}}
    assert type(decode_value(v)["a"][2]) is int


@pytest.mark.parametrize("bad", [
    {"kind": "expr"},
    {"kind": "int", "value": True},
    {"kind": "bool", "value": 1},
    {"kind": "list"},
    {"kind": "dict", "items": [{"kind": "int", "value": 1}]},
    {"kind": "pickle", "value": "x"},
    {"kind": "int", "value": 1, "extra": 2},
])
def test_encoded_value_validation(bad):
    with pytest.raises(ValueError):
        EncodedValue.model_validate(bad)


def test_decode_value_refuses_hostile_srepr():
    with pytest.raises(RebuildError):
        decode_value(EncodedValue(kind="expr", srepr="__import__('os')"))


# --------------------------------------------------------------------------- the node form

def _through_nodes(expr):
    """What the grader rebuilds from the nodes a sandbox child sends (through JSON, as they travel)."""
    nodes = expr_nodes(expr)
    assert nodes is not None
    return rebuild_nodes(json.loads(json.dumps(nodes)))


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow], derandomize=True)
@given(expr=expressions)
def test_nodes_rebuild_what_srepr_text_rebuilds(expr):
    huge = [f for f in expr.atoms(sp.Float) if f != 0 and not 1e-300 < abs(f) < 1e300]
    assume(not huge)
    via_text = rebuild_srepr(srepr_text(expr))
    if expr_nodes(expr) is None:  # left to srepr text, as designed, only for what the nodes do not take
        assert any(isinstance(a, _SREPR_ONLY) for a in sp.preorder_traversal(expr)), expr
        assert via_text == expr
        return
    via_nodes = _through_nodes(expr)
    assert via_nodes == via_text == expr
    assert sp.srepr(via_nodes) == sp.srepr(via_text)  # the same tree, not only an equal value


#: values srepr writes in a form the nodes do not take: they still travel as srepr text
_SREPR_ONLY = (sp.ImmutableMatrix, sp.Heaviside, type(sp.S.EmptySet))


@pytest.mark.parametrize("expr", [
    *EXAMPLES, sp.GoldenRatio, sp.Catalan, sp.Dummy("z", positive=True),
    sp.Eq(sp.Add(t, t, evaluate=False), 0, evaluate=False), -sp.Symbol("x"), sp.S.Zero, sp.S.NegativeOne,
])
def test_nodes_rebuild_the_examples_or_leave_them_to_srepr(expr):
    nodes = expr_nodes(expr)
    if isinstance(expr, _SREPR_ONLY):
        assert nodes is None
        return
    assert sp.srepr(_through_nodes(expr)) == sp.srepr(rebuild_srepr(srepr_text(expr)))


def test_a_repeated_subexpression_is_one_node():
    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    m, l = sp.symbols("m l", positive=True)
    L = m * l**2 * (th1.diff(t) ** 2 + th1.diff(t) * th2.diff(t) * sp.cos(th1 - th2)) + m * l * sp.cos(th1)
    nodes = expr_nodes(L)
    assert sum(n[:2] == ["Apply", "theta1"] for n in nodes) == 1
    assert sum(n[0] == "Symbol" and n[1] == "t" for n in nodes) == 1
    assert len(nodes) == len({json.dumps(n) for n in nodes})  # no node twice
    assert srepr_text(L).count("Function('theta1')") == 4


def test_taking_an_expression_apart_raises_no_audit_event():
    """The jail's child takes the answer's values apart under its audit hook, which runs on every
    audited event: ``id()`` is one (``builtins.id``), and it cost a double pendulum's values 1,100
    runs of the hook. Counted in a forked child (an audit hook cannot be removed)."""
    import os
    import sys

    th1, th2 = sp.Function("theta1")(t), sp.Function("theta2")(t)
    m, l = sp.symbols("m l", positive=True)
    L = m * l**2 * (th1.diff(t) ** 2 + th1.diff(t) * th2.diff(t) * sp.cos(th1 - th2)) + m * l * sp.cos(th1) + sp.pi / 2
    read, write = os.pipe()
    pid = os.fork()
    if pid == 0:  # pragma: no cover  (the child)
        try:
            os.close(read)
            events: list[str] = []
            sys.addaudithook(lambda event, args: events.append(event))
            nodes = expr_nodes(L)
            events = [e for e in events if e != "sys.addaudithook"]
            os.write(write, json.dumps({"events": events, "nodes": nodes}).encode())
        finally:
            os._exit(0)
    os.close(write)
    data = b""
    while chunk := os.read(read, 1 << 16):
        data += chunk
    os.close(read)
    os.waitpid(pid, 0)
    out = json.loads(data)
    assert out["events"] == []
    assert out["nodes"] == json.loads(json.dumps(expr_nodes(L)))  # what it made is what it makes here
    assert rebuild_nodes(out["nodes"]) == L and ["Const", "pi"] in out["nodes"]


def _chain(tag, n):
    return [["Symbol", "x", {}]] + [[tag, k, k] for k in range(n)]


@pytest.mark.parametrize("nodes, fragment", [
    ([], "at least one node"),
    ("Symbol('x')", "at least one node"),
    ([["Symbol", "x", {}], ["Add", 1, 0]], "not to an earlier node"),
    ([["Symbol", "x", {}], ["Add", 0, -1]], "not to an earlier node"),
    ([["Symbol", "x", {}], ["Add", 0, True]], "not to an earlier node"),
    ([["Symbol", "x", {}], ["Add", 0, "0"]], "not to an earlier node"),
    ([["Symbol", "x", {}], ["eval", 0]], "unknown constructor"),
    ([["Symbol", "x", {}], ["__import__", 0]], "unknown constructor"),
    ([["One"]], "unknown constructor"),
    ([["Integer", 1], ["Matrix", 0]], "unknown constructor"),
    ([[1, 2]], "starts with its kind"),
    (["Symbol"], "starts with its kind"),
    ([["Symbol", "x; import os", {}]], "invalid symbol name"),
    ([["Symbol", "x", {"evil": True}]], "unsupported symbol option"),
    ([["Symbol", "x", {"positive": "yes"}]], "unsupported symbol option"),
    ([["Symbol", "x"]], "name and its assumptions"),
    ([["Symbol", "t", {}], ["Apply", "f(x)", 0]], "invalid function name"),
    ([["Apply", "f"]], "needs arguments"),
    ([["Integer", True]], "integer literal"),
    ([["Integer", "1"]], "integer literal"),
    ([["Integer", 10**61]], "too large"),
    ([["Rational", 1, 10**61]], "too large"),
    ([["Float", "1e999999999", 53]], "malformed Float"),
    ([["Float", "1.0", 10**9]], "precision"),
    ([["Const", "os"]], "unknown constant"),
    ([["Const", "None"]], "unknown constant"),
    ([["Integer", 10], ["Integer", 10], ["Pow", 0, 1], ["Pow", 0, 2]], "number too large"),
    ([["Symbol", "t", {}], ["Apply", "f", 0], ["Integer", 10**9], ["Tuple", 0, 2], ["Derivative", 1, 3]],
     "derivative order"),
    (_chain("Tuple", 40), "too large"),        # 2**40 nodes as a tree, 41 as nodes
    ([["Symbol", "x", {}]] + [["sin", k] for k in range(150)], "nested too deeply"),
    ([["Integer", int("9" * 60)]] * 5000, "too many digits"),
    ([["Const", "pi"]] * (MAX_NODES + 1), "too large"),
])
def test_node_rejections(nodes, fragment):
    start = time.process_time()
    with pytest.raises(RebuildError) as info:
        rebuild_nodes(nodes)
    assert fragment in str(info.value), str(info.value)
    assert time.process_time() - start < 1


def test_encoded_expr_carries_nodes_or_srepr_not_both():
    with pytest.raises(ValueError):
        EncodedValue.model_validate({"kind": "expr", "srepr": "Symbol('x')", "nodes": [["Symbol", "x", {}]]})
    v = EncodedValue.model_validate({"kind": "expr", "nodes": [["Symbol", "x", {}], ["Integer", 2], ["Pow", 0, 1]]})
    assert decode_value(v) == sp.Symbol("x") ** 2
