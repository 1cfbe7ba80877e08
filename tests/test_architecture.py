"""The house reads as the pipeline: import-linter's contracts (pyproject.toml) hold, and no module
imports itself back through others (an import circle), lazy imports inside functions included."""

from __future__ import annotations

from pathlib import Path

import grimp
from importlinter.cli import lint_imports

ROOT = Path(__file__).resolve().parents[1]


def test_the_import_contracts_hold(monkeypatch, capsys):
    monkeypatch.chdir(ROOT)  # import-linter reads pyproject.toml from the working directory
    code = lint_imports(no_cache=True, no_logo=True)
    assert code == 0, capsys.readouterr().out


def circles(graph: grimp.ImportGraph) -> list[list[str]]:
    """Strongly connected components of more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = [0]

    def visit(v: str) -> None:
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph.find_modules_directly_imported_by(v):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for module in sorted(graph.modules):
        if module not in index:
            visit(module)
    return found


def test_no_import_circles():
    graph = grimp.build_graph("lagrade", exclude_type_checking_imports=True)
    assert circles(graph) == []


def test_a_circle_is_found():
    """The search above is not vacuous: an added import back from the derivation to the checkers
    makes a circle."""
    graph = grimp.build_graph("lagrade", exclude_type_checking_imports=True)
    graph.add_import(importer="lagrade.reference", imported="lagrade.checkers.dynamics")
    assert any({"lagrade.reference", "lagrade.checkers.dynamics"} <= set(c) for c in circles(graph))
