"""A Jupyter notebook read as an answer: its code cells, as the Python text of an ``answer.py``.

The notebook is data. Its JSON is parsed here (bounded in size and nesting, never by a library that
would run anything), its outputs are ignored, and the code cells are joined into one source that
goes through the same screen and jail as an ``answer.py`` (`lagrade.answer.jail.sandbox`). What is
IPython and not Python is left out with a note: ``%`` and ``!`` lines, ``%%`` cells. The cell that
calls ``lagrade.check`` (the template's last, tagged ``lagrade-check``) checks the notebook from inside
Jupyter; it is not part of the answer, and is left out too.
"""

from __future__ import annotations

import ast
import json
import re
from dataclasses import dataclass, field
from pathlib import Path

#: a notebook holds its outputs (pictures too): larger than an answer.py, bounded all the same
MAX_NOTEBOOK_BYTES = 5_000_000
#: a notebook's JSON is 5 or 6 levels deep; far deeper is not a notebook (and costs the parser a stack)
MAX_JSON_DEPTH = 64
#: the tag of the template's check cell (``lagrade template ID --notebook``)
CHECK_TAG = "lagrade-check"

_STRING = re.compile(r'"(?:[^"\\]|\\.)*"', re.DOTALL)
_BRACKET = re.compile(r"[\[\]{}]")


class NotebookError(ValueError):
    """One line: why a file is not a notebook lagrade can read, and what was expected."""


@dataclass
class NotebookSource:
    """The answer's Python text, where each of its lines came from, and what was left out."""

    source: str
    #: for each line of ``source`` (0-based), (cell number counted from 1 over all cells, line in the cell)
    origin: list[tuple[int, int]] = field(default_factory=list)
    #: one line each: what was left out of the answer, and why
    notes: list[str] = field(default_factory=list)

    def where(self, line: int | None) -> str:
        """``cell 3, line 2`` for a line of the joined source (1-based), as a student finds it."""
        if line is None or not 1 <= line <= len(self.origin):
            return ""
        cell, inner = self.origin[line - 1]
        return f"cell {cell}, line {inner}"


def json_depth(text: str) -> int:
    """How deeply ``text``'s arrays and objects nest, counted without parsing it (strings skipped)."""
    depth = deepest = 0
    for bracket in _BRACKET.findall(_STRING.sub("", text)):
        depth += 1 if bracket in "[{" else -1
        deepest = max(deepest, depth)
    return deepest


def read_notebook(path: Path) -> NotebookSource:
    """The code cells of the notebook at ``path`` as one Python source; :class:`NotebookError` when the
    file is too large, not JSON, or not a notebook."""
    try:
        size = path.stat().st_size
        if size > MAX_NOTEBOOK_BYTES:
            raise NotebookError(f"the notebook is larger than {MAX_NOTEBOOK_BYTES // 1_000_000} MB "
                                f"(clear its outputs: Edit > Clear Outputs of All Cells)")
        text = path.read_bytes().decode("utf-8")
    except UnicodeDecodeError:
        raise NotebookError("the notebook is not valid UTF-8 text") from None
    except OSError as exc:
        raise NotebookError(f"cannot read the file: {exc.strerror or exc}") from None
    return notebook_source(text)


def notebook_source(text: str) -> NotebookSource:
    """The code cells of a notebook's JSON ``text`` as one Python source (see :func:`read_notebook`)."""
    if len(text) > MAX_NOTEBOOK_BYTES:
        raise NotebookError(f"the notebook is larger than {MAX_NOTEBOOK_BYTES // 1_000_000} MB")
    if json_depth(text) > MAX_JSON_DEPTH:
        raise NotebookError(f"not a Jupyter notebook: its JSON nests deeper than {MAX_JSON_DEPTH} levels")
    try:
        nb = json.loads(text)
    except (ValueError, RecursionError) as exc:
        where = f" (line {exc.lineno})" if isinstance(exc, json.JSONDecodeError) else ""
        raise NotebookError(f"not a Jupyter notebook: the file is not valid JSON{where}") from None
    expected = "expected a Jupyter notebook (nbformat 4: a JSON object with a list of 'cells')"
    if not isinstance(nb, dict) or not isinstance(nb.get("cells"), list):
        raise NotebookError(f"not a Jupyter notebook: {expected}")
    if nb.get("nbformat") != 4:
        raise NotebookError(f"a notebook of format {nb.get('nbformat')!r} cannot be read: {expected}; "
                            "open and save it in a current Jupyter")
    out = NotebookSource(source="")
    lines: list[str] = []
    for number, cell in enumerate(nb["cells"], start=1):
        if not isinstance(cell, dict):
            raise NotebookError(f"not a Jupyter notebook: cell {number} is not an object; {expected}")
        if cell.get("cell_type") != "code":
            continue
        source = cell.get("source", "")
        if isinstance(source, list) and all(isinstance(s, str) for s in source):
            source = "".join(source)
        if not isinstance(source, str):
            raise NotebookError(f"not a Jupyter notebook: cell {number}'s source is not text; {expected}")
        if _is_check_cell(cell, source):
            continue
        if source.lstrip().startswith("%%"):
            magic = source.lstrip().split(None, 1)[0]
            out.notes.append(f"cell {number}: '{magic}' makes the cell IPython's, not Python: the cell is "
                             f"left out of your answer")
            continue
        for inner, line in enumerate(source.removesuffix("\n").split("\n"), start=1):
            stripped = line.lstrip()
            if stripped.startswith(("%", "!")):
                out.notes.append(f"cell {number}, line {inner}: '{_short(stripped)}' is an IPython command, not "
                                 f"Python: left out of your answer")
                line = ""
            lines.append(line)
            out.origin.append((number, inner))
    out.source = "\n".join(lines) + ("\n" if lines else "")
    return out


def _short(text: str, width: int = 40) -> str:
    return text if len(text) <= width else text[: width - 3] + "..."


def _is_check_cell(cell: dict, source: str) -> bool:
    """The template's check cell, or any cell that only imports lagrade and calls ``lagrade.check``:
    Jupyter's way to check the notebook, not part of the answer (it would be refused in the jail)."""
    meta = cell.get("metadata")
    tags = meta.get("tags") if isinstance(meta, dict) else None
    if isinstance(tags, list) and CHECK_TAG in tags:
        return True
    if "lagrade" not in source:
        return False
    try:
        body = ast.parse(source).body
    except (SyntaxError, ValueError, RecursionError, MemoryError):
        return False
    return bool(body) and all(_is_check_statement(node) for node in body)


def _is_check_statement(node: ast.stmt) -> bool:
    if isinstance(node, ast.Import):
        return all(alias.name == "lagrade" for alias in node.names)
    if isinstance(node, ast.ImportFrom):
        return node.module == "lagrade" and all(alias.name == "check" for alias in node.names)
    value = node.value if isinstance(node, (ast.Expr, ast.Assign)) else None
    if isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id == "display":
        value = value.args[0] if len(value.args) == 1 else None
    if not isinstance(value, ast.Call):
        return False
    func = value.func
    return (isinstance(func, ast.Attribute) and func.attr == "check" and isinstance(func.value, ast.Name)
            and func.value.id == "lagrade") or (isinstance(func, ast.Name) and func.id == "check")
