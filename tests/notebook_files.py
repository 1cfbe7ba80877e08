"""Notebooks for the tests (a module of its own name: tests/ has no package): an answer.py's text as the code cells of an nbformat 4 notebook."""

from __future__ import annotations

import json
import re
from pathlib import Path


def cells_of(source: str) -> list[str]:
    """The source cut at its blank lines between top-level statements, as a student's cells would be."""
    blocks = re.split(r"\n\s*\n(?=\S)", source.strip("\n"))
    return [b for b in blocks if b.strip()]


def notebook(cells: list[dict]) -> dict:
    for i, cell in enumerate(cells):
        cell.setdefault("id", f"cell-{i}")
        cell.setdefault("metadata", {})
        if cell["cell_type"] == "code":
            cell.setdefault("outputs", [])
            cell.setdefault("execution_count", None)
    return {"cells": cells, "metadata": {"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                        "language": "python"}},
            "nbformat": 4, "nbformat_minor": 5}


def code(text: str, **extra) -> dict:
    return {"cell_type": "code", "source": text.splitlines(keepends=True), **extra}


def markdown(text: str) -> dict:
    return {"cell_type": "markdown", "source": text}


def as_notebook(source: str, path: Path, *, before: list[dict] = (), after: list[dict] = ()) -> Path:
    """``source`` (an answer.py's text) as a notebook at ``path``: a Markdown cell, then one code cell per
    block, each with an output a kernel could have left (outputs are never read)."""
    cells = [markdown("# My answer\nThe Lagrangian is $L = T - V$.")] + list(before)
    for block in cells_of(source):
        cells.append(code(block, outputs=[{"output_type": "stream", "name": "stdout", "text": ["L = 42\n"]}],
                          execution_count=1))
    cells += list(after)
    path.write_text(json.dumps(notebook(cells), indent=1), encoding="utf-8")
    return path
