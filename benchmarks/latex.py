"""LaTeX readers: lagrade's path against sympy's ANTLR and Lark backends (issue 24 §2).

lagrade reads one item of a LaTeX answer in three steps (``reading/latex.py``): its pre-pass rewrites
the student's text into LaTeX that sympy's grammar reads as meant, a reader turns that into an
unevaluated sympy tree (``latex._sympy_parse``: the subset reader ``reading/latex_subset.py``, or
sympy's ANTLR parser where the subset reader declines), and a rebuild maps names and allows only
what an answer may hold. This script swaps the middle step for each reader and measures:

* ``lagrade``: ``latex._sympy_parse`` as ``reading/latex.py`` uses it (subset reader, else ANTLR);
* ``antlr``: ``sympy.parsing.latex.parse_latex(text, strict=True)`` (sympy's default backend);
* ``lark``: ``parse_latex(text, backend="lark")`` (needs ``pip install lark``).

Corpora: the LaTeX items of the bulk benchmark's class (``benchmarks/bulk.py``: 200 submissions of
12.14, each distinct TOML answer weighted by its copies), every LaTeX answer under ``tests/answers``
(what ``tests/test_latex_subset.py`` reads), that test's grammar corners (``CORNERS`` and the texts the
subset reader must decline) and texts drawn from its hypothesis strategy for answers (fixed seed).
Answer items are compared after the rebuild (what grading sees); corners and generated texts, which
have no problem around them, as trees.

For every reader and corpus: items it reads to lagrade's result (``==``, or ``simplify(a - b) == 0``
where the structure differs), items it reads to something else, items it declines (an error, or
for Lark an ambiguous parse ``_ambig`` instead of an expression) that lagrade reads, texts lagrade
refuses that it reads; the median CPU time of one item (median of ``--repeats`` warm calls, sympy's
cache as a grader has it unless ``--clear-cache``); for the class, the sum over its items with their
copies; and, in fresh interpreters that have imported sympy, the CPU of importing the reader and
reading a first item (grammar load included; median of 3).

    python benchmarks/latex.py                   # everything (6 min of CPU, most of it Lark's)
    python benchmarks/latex.py --generated 0     # without the generated texts
    python benchmarks/latex.py --show-wrong      # list the items a reader gets wrong or declines
"""

from __future__ import annotations

import argparse
import contextlib
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

BENCH = Path(__file__).resolve().parent
REPO = BENCH.parent
sys.path.insert(0, str(BENCH))
sys.path.insert(0, str(REPO / "tests"))

import sympy as sp

from lagrade.answer.reading import latex, latex_subset

#: an item every reader reads (Lark declines most of what the pre-pass writes: see --show-wrong)
SAMPLE = r"\frac{1}{2} m v^2 + m g l \cos(\theta)"
#: what each reader costs before its first item, run in a fresh interpreter after ``import sympy``
FIRST_USE = {
    "lagrade": "from lagrade.answer.reading import latex\nlatex._sympy_parse(S)",
    "antlr": "from sympy.parsing.latex import parse_latex\nparse_latex(S, strict=True)",
    "lark": "from sympy.parsing.latex import parse_latex\nparse_latex(S, backend='lark')",
}
PROBE = ("import sys, time\nimport sympy\nS = sys.argv[1]\nt = time.process_time()\n{code}\n"
         "print(time.process_time() - t)")


class Declined(Exception):
    """The reader gave no sympy expression."""


# --------------------------------------------------------------------------- readers

def _lagrade_reader() -> Callable[[str], Any]:
    return latex._sympy_parse


def _antlr_reader() -> Callable[[str], Any]:
    from sympy.parsing.latex import parse_latex

    return lambda text: parse_latex(text, strict=True)


def _lark_reader() -> Callable[[str], Any] | None:
    try:
        import lark  # noqa: F401
    except ImportError:
        return None
    from sympy.parsing.latex import parse_latex

    def read(text: str) -> Any:
        tree = parse_latex(text, backend="lark")
        if not isinstance(tree, sp.Basic):  # Earley's explicit ambiguity: a lark Tree('_ambig', ...)
            raise Declined(f"ambiguous: {type(tree).__name__} {getattr(tree, 'data', '')}")
        return tree

    return read


# --------------------------------------------------------------------------- corpora

class Piece:
    """One item of an answer: the reader's input (pre-pass text) and what rebuilds it."""

    def __init__(self, names: Any, tokens: list[str], text: str) -> None:
        self.names, self.tokens, self.text = names, tokens, text

    def result(self, reader: Callable[[str], Any]) -> Any:
        """The item as grading sees it, with ``reader`` in place of ``latex._sympy_parse``."""
        real = latex._sympy_parse
        latex._sympy_parse = reader
        try:
            return self.names.parse_piece(list(self.tokens))
        finally:
            latex._sympy_parse = real


class Text:
    """A text in sympy's grammar with no problem around it: compared as trees."""

    def __init__(self, text: str) -> None:
        self.text = text

    def result(self, reader: Callable[[str], Any]) -> Any:
        return reader(self.text)


def answer_pieces(paths: list[tuple[Path, str]]) -> dict[Path, list[Piece]]:
    """Every LaTeX item of each answer file, captured while lagrade loads it."""
    from lagrade.answer.reading.load import load_answer
    from lagrade.problem.library import load_problem

    out: dict[Path, list[Piece]] = {}
    real_piece, real_parse = latex._Names.parse_piece, latex._sympy_parse
    current: list[Piece] = []

    def piece(self: Any, tokens: list[str]) -> Any:
        seen: list[str] = []

        def parse(text: str) -> Any:
            seen.append(text)
            return real_parse(text)

        latex._sympy_parse = parse
        try:
            return real_piece(self, tokens)
        finally:
            latex._sympy_parse = real_parse
            if seen:
                current.append(Piece(self, list(tokens), seen[0]))

    latex._Names.parse_piece = piece
    try:
        for path, problem in paths:
            current = []
            load_answer(path, load_problem(problem))
            out[path] = current
    finally:
        latex._Names.parse_piece = real_piece
    return out


def class_answers(tmp: Path, problem: str, size: int) -> tuple[list[Path], Counter, int]:
    """The bulk benchmark's class, made in ``tmp``: its distinct TOML answers (one file each), their
    copies, and the number of TOML answers."""
    import hashlib

    import bulk

    root, _, _ = bulk.make(tmp, size, problem)
    copies: Counter = Counter()
    first: dict[str, bytes] = {}
    for f in sorted(root.rglob("*.toml")):
        key = hashlib.sha256(f.read_bytes()).hexdigest()
        copies[key] += 1
        first.setdefault(key, f.read_bytes())
    paths, weights = [], Counter()
    for i, (key, data) in enumerate(sorted(first.items())):
        p = tmp / "distinct" / f"{i}.toml"
        p.parent.mkdir(exist_ok=True)
        p.write_bytes(data)
        paths.append(p)
        weights[p] = copies[key]
    return paths, weights, sum(copies.values())


def generated_texts(n: int) -> list[str]:
    """``n`` draws of tests/test_latex_subset.py's strategy for answers, derandomized."""
    if n <= 0:
        return []
    import test_latex_subset as t
    from hypothesis import HealthCheck, Phase, given, settings

    texts: list[str] = []

    @settings(max_examples=n, derandomize=True, database=None, deadline=None, phases=[Phase.generate],
              suppress_health_check=list(HealthCheck))
    @given(t._ANSWERS)
    def collect(text: str) -> None:
        texts.append(text)

    collect()
    return list(dict.fromkeys(texts))


# --------------------------------------------------------------------------- comparing and timing

def _same(a: Any, b: Any) -> str:
    """'==' (structurally equal), 'simplify' (equal after simplify(a - b)) or 'different'."""
    if isinstance(a, list) or isinstance(b, list):
        if not (isinstance(a, list) and isinstance(b, list) and len(a) == len(b)):
            return "different"
        kinds = [_same(x, y) for x, y in zip(a, b)]
        return "different" if "different" in kinds else "simplify" if "simplify" in kinds else "=="
    if a == b:
        return "=="
    if isinstance(a, sp.Equality) != isinstance(b, sp.Equality):
        return "different"
    pairs = [(a.lhs, b.lhs), (a.rhs, b.rhs)] if isinstance(a, sp.Equality) else [(a, b)]
    try:
        for x, y in pairs:
            x, y = x.doit(), y.doit()
            if not (x == y or sp.simplify(x - y) == 0):
                return "different"
    except Exception:  # noqa: BLE001  (not expressions sympy can subtract)
        return "different"
    return "simplify"


def _outcome(item: Any, reader: Callable[[str], Any]) -> tuple[bool, Any]:
    try:
        return True, item.result(reader)
    except Exception as exc:  # noqa: BLE001  (a refusal or a crash: the reader did not read it)
        return False, f"{type(exc).__name__}: {str(exc).splitlines()[0][:100] if str(exc) else ''}"


def _cpu(reader: Callable[[str], Any], text: str, repeats: int, clear: bool) -> float:
    """Median CPU seconds of one warm call (errors included: refusing costs time too)."""
    from sympy.core.cache import clear_cache

    def once() -> None:
        with contextlib.suppress(Exception):  # refusing costs time too
            reader(text)

    once()
    times = []
    for _ in range(repeats):
        if clear:
            clear_cache()
        t = time.process_time()
        once()
        times.append(time.process_time() - t)
    return statistics.median(times)


def first_use(reader: str) -> float | None:
    runs = []
    for _ in range(3):
        out = subprocess.run([sys.executable, "-c", PROBE.format(code=FIRST_USE[reader]), SAMPLE],
                             capture_output=True, text=True, check=False)
        if out.returncode:
            return None
        runs.append(float(out.stdout.split()[-1]))
    return statistics.median(runs)


# --------------------------------------------------------------------------- main

def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--problem", default="12.14", help="the bulk benchmark's class problem (default 12.14)")
    ap.add_argument("--size", type=int, default=200, help="submissions in the class (default 200)")
    ap.add_argument("--generated", type=int, default=200, help="texts drawn from the test's strategy")
    ap.add_argument("--repeats", type=int, default=5, help="timed calls per item; the median is kept")
    ap.add_argument("--clear-cache", action="store_true", help="clear sympy's cache before each timed call")
    ap.add_argument("--show-wrong", action="store_true", help="list what each reader gets wrong or declines")
    args = ap.parse_args()

    readers = {"lagrade": _lagrade_reader(), "antlr": _antlr_reader(), "lark": _lark_reader()}
    if readers["lark"] is None:
        print("lark is not installed (pip install lark): the lark rows are skipped")
    readers = {k: v for k, v in readers.items() if v is not None}

    tmp = Path(tempfile.mkdtemp(prefix="lagrade-latex-bench-"))
    try:
        class_paths, weights, n_toml = class_answers(tmp, args.problem, args.size)
        class_pieces = answer_pieces([(p, args.problem) for p in class_paths])
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    golden = sorted(p for p in (REPO / "tests" / "answers").glob("*/*.toml") if "\\" in p.read_text())
    golden_pieces = answer_pieces([(p, p.parent.name) for p in golden])
    import test_latex_subset as t

    must_decline = [s for m in t.test_the_reader_declines_what_it_does_not_know.pytestmark
                    if m.name == "parametrize" for s in m.args[1]]
    corners = list(dict.fromkeys(t.CORNERS + must_decline))
    corpora: dict[str, list[tuple[Any, int]]] = {
        f"class ({args.problem})": [(p, weights[path]) for path, ps in class_pieces.items() for p in ps],
        "tests/answers": [(p, 1) for ps in golden_pieces.values() for p in ps],
        "corners": [(Text(s), 1) for s in corners],
        "generated": [(Text(s), 1) for s in generated_texts(args.generated)],
    }
    latex_files = sum(1 for ps in class_pieces.values() if ps)
    print(f"class: {n_toml} TOML answers of {args.problem} in {args.size} submissions, "
          f"{sum(weights[p] for p, ps in class_pieces.items() if ps)} of them LaTeX ({latex_files} distinct files, "
          f"{len(corpora[f'class ({args.problem})'])} distinct items); tests/answers: {len(golden)} LaTeX files, "
          f"{len(corpora['tests/answers'])} items; corners: {len(corners)}; generated: "
          f"{len(corpora['generated'])}")

    firsts = {name: first_use(name) for name in readers}
    rows, wrong = [], []
    for corpus, items in corpora.items():
        if not items:
            continue
        ref = [_outcome(item, readers["lagrade"]) for item, _ in items]
        subset = sum(latex_subset.read(item.text, latex._NUMBERS_READ) is not None for item, _ in items)
        for name, reader in readers.items():
            tally: Counter = Counter()
            cpu, agreed, total = [], [], 0.0
            for (item, weight), (ok_ref, want) in zip(items, ref):
                ok, got = (ok_ref, want) if name == "lagrade" else _outcome(item, reader)
                kind = None
                if ok and ok_ref:
                    kind = _same(got, want)
                    tally[kind] += 1
                    if kind == "different":
                        wrong.append((name, corpus, item.text, f"{got}  (lagrade: {want})"))
                elif ok_ref:
                    tally["declined"] += 1
                    wrong.append((name, corpus, item.text, f"declined: {got}"))
                elif ok:
                    tally["extra"] += 1
                    wrong.append((name, corpus, item.text, f"lagrade refuses ({want}), this reads {got}"))
                else:
                    tally["both refuse"] += 1
                c = _cpu(reader, item.text, args.repeats, args.clear_cache)
                cpu.append(c)
                if ok and ok_ref and kind != "different":
                    agreed.append(c)
                total += c * weight
            rows.append((corpus, name, len(items), tally, statistics.median(cpu) if cpu else 0.0,
                         statistics.median(agreed) if agreed else None,
                         total if corpus.startswith("class") else None,
                         subset if name == "lagrade" else None))

    print()
    print(f"{'corpus':<16} {'reader':<8} {'items':>5} {'==':>5} {'simpl':>5} {'wrong':>5} {'decl':>5} "
          f"{'extra':>5} {'refuse':>6} {'ms/item':>8} {'ms ok':>6} {'class ms':>9} {'1st use s':>9}")
    for corpus, name, n, tally, med, med_ok, total, subset in rows:
        first = firsts.get(name)
        print(f"{corpus:<16} {name:<8} {n:>5} {tally['==']:>5} {tally['simplify']:>5} {tally['different']:>5} "
              f"{tally['declined']:>5} {tally['extra']:>5} {tally['both refuse']:>6} {med * 1000:>8.2f} "
              f"{'' if med_ok is None else f'{med_ok * 1000:.2f}':>6} "
              f"{'' if total is None else f'{total * 1000:.0f}':>9} {'' if first is None else f'{first:.2f}':>9}"
              + ("" if subset is None else f"   (subset reader: {subset}/{n})"))
    print()
    print("==: the same expression as lagrade's; simpl: equal after simplify(a - b); wrong: another expression;"
          "\ndecl: declined (an error, or lark's ambiguous parse) where lagrade reads it; extra: read where lagrade "
          "refuses;\nrefuse: both refuse. ms/item: median over the items of the median CPU of "
          f"{args.repeats} warm calls{' (sympy cache cleared)' if args.clear_cache else ''}; ms ok: the same over the "
          "items it reads to lagrade's result;\nclass ms: the class's "
          "LaTeX items with their copies;\n1st use s: CPU to import the reader and read one item in a fresh "
          "interpreter after `import sympy` (median of 3).")
    if args.show_wrong:
        print()
        for name, corpus, text, what in wrong:
            if name != "lagrade":
                print(f"{name:<6} {corpus:<14} {text!r}: {what}")


if __name__ == "__main__":
    main()
