"""Rebuild sympy objects from what an untrusted sandbox child sends (nodes or ``srepr`` text), without ``eval``.

The sandbox sends a student's values back as JSON.  Evaluating them would hand the student's process a
way into the grader, so only calls to an allowlist of sympy constructors are performed, on one of
two forms: a list of nodes, each distinct subexpression once (:func:`expr_nodes`, what the child
sends for the expressions answers are made of: it is read ten times faster), or ``sympy.srepr``
text parsed with ``ast`` (anything else). Number sizes, nesting and exact numeric powers are bounded
*before* sympy gets to work, so that hostile input such as ``Pow(Integer(10), Pow(Integer(10),
Integer(10)))`` fails fast instead of hanging the grader.
"""

from __future__ import annotations

import ast
import re
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any, Literal

import sympy as sp
from pydantic import (
    BaseModel,
    ConfigDict,
    StrictBool,
    StrictFloat,
    StrictInt,
    StrictStr,
    model_validator,
)
from sympy.core.assumptions import _assume_defined
from sympy.core.function import AppliedUndef, UndefinedFunction

from lagrade.problem.notation import (  # the limits on any untrusted math text, shared with the notation reader
    MAX_DEPTH,
    MAX_DERIVATIVE_ORDER,
    MAX_FLOAT_PRECISION,
    MAX_NODES,
    MAX_TOTAL_INT_DIGITS,
    RebuildError,
    check_combined,
    check_derivative,
    check_int,
    check_name,
    check_power,
    derivative_count,
    parse_limited,
)

_FLOAT_TEXT = re.compile(r"^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d{1,5})?$|^[+-]?(inf|nan)$", re.I)




class EncodedValue(BaseModel):
    """A student's value as it crosses from the sandbox: plain JSON, never pickles.

    ``expr`` carries its nodes (:func:`expr_nodes`) or ``srepr`` text; ``list``/``dict`` nest (a
    dict as ``[key, value]`` pairs).
    """

    model_config = ConfigDict(extra="forbid", frozen=True)

    kind: Literal["expr", "bool", "int", "float", "str", "list", "dict"]
    srepr: StrictStr | None = None
    nodes: list[list[Any]] | None = None
    value: StrictBool | StrictInt | StrictFloat | StrictStr | None = None
    items: list[EncodedValue] | list[tuple[EncodedValue, EncodedValue]] | None = None

    @model_validator(mode="after")
    def _consistent(self) -> EncodedValue:
        expected = {"bool": bool, "int": int, "float": float, "str": str}.get(self.kind)
        if self.kind == "expr" and (self.srepr is None) == (self.nodes is None):
            raise ValueError("an expr needs srepr or nodes, not both")
        if expected is not None and (type(self.value) is not expected):
            if not (self.kind == "float" and type(self.value) is int):
                raise ValueError(f"a {self.kind} needs a {expected.__name__} value")
        if self.kind in ("list", "dict"):
            if self.items is None:
                raise ValueError(f"a {self.kind} needs items")
            pairs = [isinstance(i, tuple) for i in self.items]
            if self.items and any(pairs) != (self.kind == "dict"):
                raise ValueError(f"bad items for a {self.kind}")
        return self


def decode_value(v: EncodedValue) -> Any:
    """Turn an :class:`EncodedValue` back into Python/sympy objects (exprs via :func:`rebuild_srepr`)."""
    return _decode(v, 0)


def _decode(v: EncodedValue, depth: int) -> Any:
    if depth > 50:
        raise RebuildError("value nested too deeply")
    if v.kind == "expr":
        return rebuild_nodes(v.nodes) if v.nodes is not None else rebuild_srepr(v.srepr or "")
    if v.kind == "float":
        return float(v.value)  # type: ignore[arg-type]
    if v.kind in ("bool", "int", "str"):
        return v.value
    if v.kind == "list":
        return [_decode(i, depth + 1) for i in v.items or []]  # type: ignore[arg-type]
    out: dict[Any, Any] = {}
    for key, val in v.items or []:  # type: ignore[misc]
        k = _decode(key, depth + 1)
        if isinstance(k, list):
            k = tuple(k)
        try:
            out[k] = _decode(val, depth + 1)
        except TypeError as exc:
            raise RebuildError(f"unusable dict key: {exc}") from None
    return out


# --------------------------------------------------------------------------- srepr constructors

def _symbol(name: Any, **assumptions: Any) -> sp.Symbol:
    return sp.Symbol(check_name(name, "symbol name"), **_assumptions(assumptions))


def _dummy(name: Any, dummy_index: Any = None, **assumptions: Any) -> sp.Symbol:
    return _symbol(name, **assumptions)  # a Dummy's identity cannot cross processes; a Symbol is honest


def _function(name: Any, **assumptions: Any) -> UndefinedFunction:
    return sp.Function(check_name(name, "function name"), **_assumptions(assumptions))


def _assumptions(kwargs: dict[str, Any]) -> dict[str, bool]:
    for key, value in kwargs.items():
        if key not in _assume_defined or not isinstance(value, bool):
            raise RebuildError(f"unsupported symbol option {key}={value!r}")
    return kwargs


def _integer(value: Any) -> sp.Integer:
    if not isinstance(value, int) or isinstance(value, bool):
        raise RebuildError("Integer() needs an integer literal")
    check_int(value)
    return sp.Integer(value)


def _rational(p: Any, q: Any = 1) -> sp.Rational:
    parts = [int(x) if isinstance(x, sp.Integer) else x for x in (p, q)]
    if not all(isinstance(x, int) and not isinstance(x, bool) for x in parts):
        raise RebuildError("Rational() needs integer arguments")
    for x in parts:
        check_int(x)
    if parts[1] == 0:
        return sp.zoo if parts[0] else sp.nan
    return sp.Rational(*parts)


def _float(value: Any, precision: Any = 53, dps: Any = None) -> sp.Float:
    if dps is not None:
        if not isinstance(dps, int) or isinstance(dps, bool) or not 1 <= dps <= MAX_FLOAT_PRECISION // 3:
            raise RebuildError("Float dps out of range")
        precision = None
    elif not isinstance(precision, int) or isinstance(precision, bool) or not 1 <= precision <= MAX_FLOAT_PRECISION:
        raise RebuildError("Float precision out of range")
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        value = repr(value)
    if not isinstance(value, str) or len(value) > 4000 or not _FLOAT_TEXT.match(value.strip()):
        raise RebuildError(f"malformed Float literal {str(value)[:40]!r}")
    return sp.Float(value, dps=dps) if dps is not None else sp.Float(value, precision=precision)


def _pow(base: Any, exp: Any) -> sp.Expr:
    check_power(base, exp)
    return sp.Pow(base, exp)


def _derivative(expr: Any, *variables: Any) -> sp.Expr:
    for v in variables:
        count = v[1] if isinstance(v, (tuple, sp.Tuple)) and len(v) == 2 else 1
        if isinstance(count, (int, sp.Integer)) and not 0 <= int(count) <= MAX_DERIVATIVE_ORDER:
            raise RebuildError(f"derivative order {count} out of range")
    check_derivative(expr, derivative_count(variables))  # the engine may carry it out
    return sp.Derivative(expr, *variables)


def _add(*args: Any) -> Any:
    check_combined(args, product=False)
    return sp.Add(*args)


def _mul(*args: Any) -> Any:
    check_combined(args, product=True)
    return sp.Mul(*args)


def _matrix(rows: Any) -> sp.ImmutableMatrix:
    if not isinstance(rows, list) or not all(isinstance(r, list) for r in rows):
        raise RebuildError("Matrix() needs a list of rows")
    return sp.ImmutableMatrix(rows)


def _unevaluated(relation: Any):
    def build(lhs: Any, rhs: Any) -> Any:
        return relation(lhs, rhs, evaluate=False)
    return build


def _const(value: Any):
    return lambda: value


_CONSTRUCTORS: dict[str, Any] = {
    "Symbol": _symbol, "Dummy": _dummy, "Function": _function,
    "Integer": _integer, "Rational": _rational, "Float": _float, "Pow": _pow,
    "Add": _add, "Mul": _mul, "Derivative": _derivative, "Tuple": sp.Tuple,
    # relations are rebuilt as written: srepr shows them after the student's own evaluation
    "Equality": _unevaluated(sp.Eq), "Eq": _unevaluated(sp.Eq), "Unequality": _unevaluated(sp.Ne),
    "Ne": _unevaluated(sp.Ne), "StrictLessThan": _unevaluated(sp.Lt),
    "StrictGreaterThan": _unevaluated(sp.Gt), "LessThan": _unevaluated(sp.Le),
    "GreaterThan": _unevaluated(sp.Ge),
    "And": sp.And, "Or": sp.Or, "Not": sp.Not,
    "Integral": sp.Integral, "Subs": sp.Subs, "Order": sp.Order,
    "FiniteSet": sp.FiniteSet, "AccumulationBounds": sp.AccumBounds,
    "Piecewise": sp.Piecewise, "ExprCondPair": sp.functions.elementary.piecewise.ExprCondPair,
    "MutableDenseMatrix": _matrix, "ImmutableDenseMatrix": _matrix, "Matrix": _matrix,
    "ImmutableMatrix": _matrix,
    # singletons as they appear when srepr is given S.Half etc. directly
    "Half": _const(sp.S.Half), "One": _const(sp.S.One), "Zero": _const(sp.S.Zero),
    "NegativeOne": _const(sp.S.NegativeOne), "Pi": _const(sp.pi), "Exp1": _const(sp.E),
    "ImaginaryUnit": _const(sp.I), "Infinity": _const(sp.oo), "NegativeInfinity": _const(-sp.oo),
    "ComplexInfinity": _const(sp.zoo), "NaN": _const(sp.nan), "EulerGamma": _const(sp.EulerGamma),
    "BooleanTrue": _const(sp.true), "BooleanFalse": _const(sp.false),
}
for _name in ("sin cos tan cot sec csc asin acos atan acot asec acsc atan2 sinh cosh tanh coth "
              "asinh acosh atanh acoth exp log sqrt cbrt Abs sign re im arg conjugate floor ceiling "
              "Max Min Heaviside DiracDelta").split():
    _CONSTRUCTORS[_name] = getattr(sp, _name)

_CONSTANTS: dict[str, Any] = {
    "pi": sp.pi, "E": sp.E, "I": sp.I, "oo": sp.oo, "zoo": sp.zoo, "nan": sp.nan,
    "true": sp.true, "false": sp.false, "EulerGamma": sp.EulerGamma, "GoldenRatio": sp.GoldenRatio,
    "Catalan": sp.Catalan, "EmptySet": sp.EmptySet, "None": None, "True": True, "False": False,
}


def srepr_text(value: Any) -> str:
    """The ``srepr`` text a sandbox child sends for a sympy object, terms and factors in the
    object's own order: `rebuild_srepr` evaluates Add and Mul, which sorts them again, so the printer's
    sort (about three quarters of ``srepr``'s time) would be done for nothing."""
    return sp.srepr(value, order="none")


def rebuild_srepr(text: str) -> Any:
    """Rebuild the sympy object whose ``sympy.srepr`` is ``text``; raises :class:`RebuildError`.

    Usually returns a ``sympy.Basic``; Python tuples/lists/dicts in the text come back as such.
    """
    tree = parse_limited(text, "srepr text")
    with _as_rebuild_error("srepr text"):
        return _Builder().build(tree.body, 0)  # type: ignore[attr-defined]


@contextmanager
def _as_rebuild_error(what: str) -> Iterator[None]:
    """What Python or sympy raise while an object is built, as a :class:`RebuildError` naming ``what``."""
    try:
        yield
    except RebuildError:
        raise
    except RecursionError:
        raise RebuildError("expression nested too deeply") from None
    except (TypeError, ValueError, AttributeError, IndexError, KeyError, ZeroDivisionError,
            OverflowError, NotImplementedError, sp.SympifyError) as exc:
        raise RebuildError(f"invalid {what}: {type(exc).__name__}: {str(exc)[:200]}") from None


class _Builder:
    def build(self, node: ast.AST, depth: int) -> Any:
        if depth > MAX_DEPTH:
            raise RebuildError(f"expression nested too deeply (more than {MAX_DEPTH} levels)")
        d = depth + 1
        if isinstance(node, ast.Constant):
            if isinstance(node.value, (str, int, float, bool)) or node.value is None:
                return node.value
            raise RebuildError(f"unsupported literal {node.value!r:.40}")
        if isinstance(node, ast.Name):
            if node.id in _CONSTANTS:
                return _CONSTANTS[node.id]
            raise RebuildError(f"unknown name {node.id[:80]!r}")
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
            value = self.build(node.operand, d)
            if isinstance(value, bool) or not isinstance(value, (int, float, sp.Expr)):
                raise RebuildError("unary minus on a non-number")
            return -value if isinstance(node.op, ast.USub) else value
        if isinstance(node, ast.Tuple):
            return tuple(self.build(e, d) for e in node.elts)
        if isinstance(node, ast.List):
            return [self.build(e, d) for e in node.elts]
        if isinstance(node, ast.Dict):
            if any(k is None for k in node.keys):
                raise RebuildError("'**' in a dict is not allowed")
            return {self.build(k, d): self.build(v, d) for k, v in zip(node.keys, node.values)}
        if isinstance(node, ast.Call):
            return self.call(node, d)
        if isinstance(node, ast.Attribute):
            raise RebuildError("attribute access is not allowed in srepr text")
        raise RebuildError(f"unsupported syntax {type(node).__name__} in srepr text")

    def call(self, node: ast.Call, depth: int) -> Any:
        func = node.func
        if isinstance(func, ast.Call):  # Function('theta')(Symbol('t'))
            if not (isinstance(func.func, ast.Name) and func.func.id == "Function"):
                raise RebuildError("only Function('name')(...) may be applied")
            ctor = self.call(func, depth)
        elif isinstance(func, ast.Name):
            if func.id not in _CONSTRUCTORS:
                raise RebuildError(f"unknown constructor {func.id[:80]!r}")
            ctor = _CONSTRUCTORS[func.id]
        else:
            raise RebuildError("only plain constructor names may be called (no attribute access)")
        if any(isinstance(a, ast.Starred) for a in node.args):
            raise RebuildError("'*' arguments are not allowed")
        args = [self.build(a, depth) for a in node.args]
        kwargs: dict[str, Any] = {}
        for kw in node.keywords:
            if kw.arg is None:
                raise RebuildError("'**' arguments are not allowed")
            value = self.build(kw.value, depth)
            if not isinstance(value, (bool, int, str)) or isinstance(value, str) and kw.arg != "name":
                raise RebuildError(f"unsupported keyword argument {kw.arg}={value!r:.40}")
            kwargs[kw.arg] = value
        if kwargs and ctor not in (_symbol, _dummy, _function, _float):
            raise RebuildError(f"keyword arguments are not allowed for {ast.unparse(func)[:40]}")
        return _construct(ctor, args, kwargs)


def _construct(ctor: Any, args: list[Any], kwargs: dict[str, Any]) -> Any:
    """Call an allowlisted constructor: both forms end here, with the same checks."""
    if isinstance(ctor, UndefinedFunction):
        if not args:
            raise RebuildError("an applied function needs arguments")
        args = [sp.sympify(a, strict=True) for a in args]
    elif ctor not in (_symbol, _dummy, _function, _float, _integer, _rational, _matrix):
        args = [_strict(a) for a in args]
    return ctor(*args, **kwargs)


def _strict(value: Any) -> Any:
    """Arguments of sympy constructors must be sympy objects (strings would be parsed by sympify)."""
    if isinstance(value, str):
        raise RebuildError("string arguments are only allowed for names and Float literals")
    if isinstance(value, tuple):
        return sp.Tuple(*(_strict(v) for v in value))
    if isinstance(value, (list, dict)) or value is None:
        raise RebuildError("unexpected list, dict or None argument")
    return sp.sympify(value, strict=True)


# --------------------------------------------------------------------------- the node form

#: constants by the name ``srepr`` gives them; the node form sends the name
_NODE_CONSTANTS: dict[str, Any] = {
    "pi": sp.pi, "E": sp.E, "I": sp.I, "oo": sp.oo, "-oo": sp.S.NegativeInfinity, "zoo": sp.zoo,
    "nan": sp.nan, "EulerGamma": sp.EulerGamma, "GoldenRatio": sp.GoldenRatio, "Catalan": sp.Catalan,
    "true": sp.true, "false": sp.false,
}
#: an object's identity as a number, unique among live objects (``object``'s own hash is its address,
#: rotated); unlike ``id()`` it raises no audit event. In the jail's child every audit event runs the
#: tripwire hook (about 1 us): ``id()`` in `expr_nodes` made 1,100 of them for a double pendulum's
#: values, 1.5 ms of the 2.5 its encoding took.
_identity = object.__hash__
_CONSTANT_NAMES = {_identity(value): name for name, value in _NODE_CONSTANTS.items()}  # singletons: by identity

#: constructors a node calls by name with its arguments, as ``srepr`` writes ``Name(arg, ...)``;
#: numbers, symbols, applied functions and constants have nodes of their own, and the rest
#: (matrices, ``Heaviside``, whose srepr leaves out an argument) goes as srepr text
_NODE_CALLS = frozenset(
    name for name, ctor in _CONSTRUCTORS.items()
    if ctor not in (_symbol, _dummy, _function, _integer, _rational, _float, _matrix)
    and name not in ("Heaviside", "Half", "One", "Zero", "NegativeOne", "Pi", "Exp1", "ImaginaryUnit",
                     "Infinity", "NegativeInfinity", "ComplexInfinity", "NaN", "EulerGamma",
                     "BooleanTrue", "BooleanFalse"))


def expr_nodes(value: Any) -> list[list[Any]] | None:
    """A sympy object as a list of nodes, each distinct subexpression once, children first, the
    value last; None if some part of it has no node form (the sandbox child then sends srepr text).

    A node is ``["Symbol", name, assumptions]``, ``["Integer", p]``, ``["Rational", p, q]``,
    ``["Float", digits, precision]``, ``["Const", name]``, ``["Apply", function name, i, ...]`` or
    ``[constructor, i, ...]``, where ``i`` is the index of an earlier node. It says what
    :func:`srepr_text` says, so both forms rebuild the same object; but an answer repeats its
    subexpressions (the double pendulum's L names theta1(t) eight times), which srepr writes out and
    the grader parses and builds each time: reading the nodes took a tenth of the time."""
    from mpmath.libmp import repr_dps
    from mpmath.libmp import to_str as mpf_text

    nodes: list[list[Any]] = []
    index: dict[int, int] = {}  # by object
    same: dict[tuple, int] = {}  # by node
    stack = [value]
    try:
        while stack:
            e = stack[-1]
            if _identity(e) in index:
                stack.pop()
                continue
            kind = type(e)
            if kind is sp.Symbol or kind is sp.Dummy:  # a Dummy is rebuilt as a Symbol either way
                node = ["Symbol", e.name, dict(e._assumptions_orig)]
            elif isinstance(e, sp.Integer):
                node = ["Integer", int(e.p)]
            elif kind is sp.Rational or kind is type(sp.S.Half):
                node = ["Rational", int(e.p), int(e.q)]
            elif kind is sp.Float:
                node = ["Float", mpf_text(e._mpf_, repr_dps(e._prec)), int(e._prec)]
            elif _identity(e) in _CONSTANT_NAMES:
                node = ["Const", _CONSTANT_NAMES[_identity(e)]]
            elif isinstance(e, sp.Basic) and (isinstance(e, AppliedUndef) or kind.__name__ in _NODE_CALLS):
                waiting = [a for a in e.args if _identity(a) not in index]
                if waiting:
                    stack.extend(reversed(waiting))
                    continue
                refs = [index[_identity(a)] for a in e.args]
                node = ["Apply", e.func.__name__, *refs] if isinstance(e, AppliedUndef) else [kind.__name__, *refs]
            else:
                return None
            stack.pop()
            # equal objects need not be one object (two Integer(2)): equal nodes are sent once
            key = (*node[:2], *sorted(node[2].items())) if node[0] == "Symbol" else tuple(node)
            if key not in same:
                same[key] = len(nodes)
                nodes.append(node)
            index[_identity(e)] = same[key]
    except Exception:  # noqa: BLE001  (an object sympy cannot take apart: srepr says what it can)
        return None
    return nodes


def rebuild_nodes(nodes: Any) -> Any:
    """Rebuild the sympy object :func:`expr_nodes` took apart; raises :class:`RebuildError`.

    The limits are srepr's: the tree the nodes stand for (each shared node counted every time it is
    used) has at most ``MAX_NODES`` nodes and ``MAX_DEPTH`` levels, so that a few nodes cannot
    stand for an expression too large to compare; every constructor is checked as in srepr text."""
    if not isinstance(nodes, list) or not nodes:
        raise RebuildError("an expression needs at least one node")
    if len(nodes) > MAX_NODES:
        raise RebuildError(f"expression too large (more than {MAX_NODES} nodes)")
    built: list[Any] = []
    sizes: list[int] = []
    depths: list[int] = []
    digits = 0
    with _as_rebuild_error("expression nodes"):
        for i, node in enumerate(nodes):
            if not isinstance(node, list) or not node or not isinstance(node[0], str):
                raise RebuildError(f"node {i} is not a list that starts with its kind")
            tag, rest = node[0], node[1:]
            size = depth = 1
            if tag == "Symbol":
                if len(rest) != 2 or not isinstance(rest[1], dict):
                    raise RebuildError("a Symbol node needs a name and its assumptions")
                value = _symbol(rest[0], **rest[1])
            elif tag in ("Integer", "Rational"):
                value = _integer(*rest) if tag == "Integer" else _rational(*rest)
                digits += sum(len(str(abs(x))) for x in rest)
                if digits > MAX_TOTAL_INT_DIGITS:
                    raise RebuildError("expression contains too many digits")
            elif tag == "Float":
                if len(rest) != 2:
                    raise RebuildError("a Float node needs its digits and precision")
                value = _float(rest[0], precision=rest[1])
            elif tag == "Const":
                if len(rest) != 1 or rest[0] not in _NODE_CONSTANTS:
                    raise RebuildError(f"unknown constant {str(rest)[:80]}")
                value = _NODE_CONSTANTS[rest[0]]
            else:
                if tag == "Apply":
                    if not rest:
                        raise RebuildError("an Apply node needs a function name")
                    ctor, refs = _function(rest[0]), rest[1:]
                elif tag in _NODE_CALLS:
                    ctor, refs = _CONSTRUCTORS[tag], rest
                else:
                    raise RebuildError(f"unknown constructor {tag[:80]!r}")
                for r in refs:
                    if type(r) is not int or not 0 <= r < i:
                        raise RebuildError(f"node {i} refers to {str(r)[:20]}, not to an earlier node")
                size += sum(sizes[r] for r in refs)
                depth += max((depths[r] for r in refs), default=0)
                if size > MAX_NODES:
                    raise RebuildError(f"expression too large (more than {MAX_NODES} syntax nodes)")
                if depth > MAX_DEPTH:
                    raise RebuildError(f"expression nested too deeply (more than {MAX_DEPTH} levels)")
                value = _construct(ctor, [built[r] for r in refs], {})
            built.append(value)
            sizes.append(size)
            depths.append(depth)
    return built[-1]
