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
    graph.add_import(importer="lagrade.derive.reference", imported="lagrade.verdicts.checkers.dynamics")
    assert any({"lagrade.derive.reference", "lagrade.verdicts.checkers.dynamics"} <= set(c) for c in circles(graph))


def _listed(text: str) -> list[tuple[int, str]]:
    block = text.split("```text\nsrc/lagrade/\n", 1)[1].split("```", 1)[0]
    return [((len(line) - len(line.lstrip(" "))) // 2, line.split()[0]) for line in block.splitlines() if line.strip()]


def test_the_tree_in_architecture_md_is_the_tree():
    """docs/architecture.md lists src/lagrade two levels deep; a module added, moved or removed
    without the listing (python scripts/tree.py prints it) fails here."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("tree", ROOT / "scripts" / "tree.py")
    tree = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(tree)
    actual = [(depth, name) for depth, name, _ in tree.listing()]
    assert _listed((ROOT / "docs" / "architecture.md").read_text(encoding="utf-8")) == actual


def test_the_top_of_the_package_is_the_layers():
    """Issue 37: `ls src/lagrade` shows the layers and nothing else but the package's own files."""
    top = {p.name for p in (ROOT / "src" / "lagrade").iterdir() if p.name != "__pycache__"}
    assert top == {"__init__.py", "__main__.py", "_version.py", "problem", "numbers", "derive", "answer",
                   "compare", "verdicts", "uses", "cli"}
