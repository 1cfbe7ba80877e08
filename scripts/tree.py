"""Print ``src/lagrade`` two levels deep, each entry with the first sentence of its docstring: the
listing in docs/architecture.md (tests/test_architecture.py checks that it is the tree)."""

from __future__ import annotations

import ast
from pathlib import Path

SRC = Path(__file__).resolve().parents[1] / "src" / "lagrade"


def summary(path: Path) -> str:
    target = path / "__init__.py" if path.is_dir() else path
    doc = ast.get_docstring(ast.parse(target.read_text(encoding="utf-8"))) or "" if target.is_file() else ""
    first = " ".join(doc.strip().split("\n\n")[0].split())
    first = first.split(". ")[0].rstrip(".").replace("``", "`")
    return first if len(first) <= 90 else first[:first.rfind(" ", 0, 88)] + " ..."


def entries(folder: Path) -> list[Path]:
    kept = [e for e in folder.iterdir() if e.name != "__pycache__" and (e.is_dir() or e.suffix == ".py")]
    return sorted(kept, key=lambda e: (not e.name.startswith("_"), e.name))


def listing() -> list[tuple[int, str, str]]:
    """(depth, name, summary) for every package and module of the first two levels."""
    rows = []
    for entry in entries(SRC):
        rows.append((1, entry.name + ("/" if entry.is_dir() else ""), summary(entry)))
        if entry.is_dir():
            for sub in entries(entry):
                if sub.name != "__init__.py":
                    rows.append((2, sub.name + ("/" if sub.is_dir() else ""), summary(sub)))
    return rows


def main() -> None:
    print("src/lagrade/")
    for depth, name, text in listing():
        indent = "  " * depth
        print(f"{indent}{name:<{26 - len(indent)}} {text}".rstrip())


if __name__ == "__main__":
    main()
