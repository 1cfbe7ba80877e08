"""Static screening of a student's ``answer.py`` before any of it runs.

An answer file only needs to build sympy expressions, so anything that reaches outside that
(imports of other modules, dunder introspection, ``eval``-like entry points, classes, exception
handling that could swallow the sandbox's own signals) is refused up front with a message the
student can act on.  This is the first of several layers; the sandbox does not rely on it alone.
"""

from __future__ import annotations

import ast
import re

from pydantic import BaseModel

MAX_SOURCE_BYTES = 200_000
MAX_PROBLEMS = 20

ALLOWED_MODULES_TEXT = "sympy, math and lagrade.answer"

#: sympy subpackages that parse strings, generate/run code, write files or start sessions.
FORBIDDEN_SYMPY_SUBMODULES = (
    "sympy.parsing",
    "sympy.utilities",
    "sympy.testing",
    "sympy.printing.preview",
    "sympy.interactive",
    "sympy.external",
)

#: Names and attributes that are refused wherever they appear.
FORBIDDEN_NAMES = frozenset({
    "open", "exec", "eval", "compile", "getattr", "setattr", "delattr", "globals",
    "locals", "vars", "input", "breakpoint", "help", "exit", "quit", "memoryview",
    "sympify", "parse_expr", "lambdify", "preview", "init_session", "init_printing",
    "sys", "os", "subprocess", "builtins", "importlib", "import_module", "ctypes",
    "var",  # sympy.var injects names through frame introspection
    "pager_print", "print_gtk", "plot", "plot_implicit", "plot_parametric", "plotting",
})

#: Attributes (``x.attr``) that lead to frames, globals, code objects or other modules.
FORBIDDEN_ATTRIBUTES = FORBIDDEN_NAMES | frozenset({
    "gi_frame", "gi_code", "gi_yieldfrom", "cr_frame", "cr_code", "cr_await",
    "ag_frame", "ag_code", "ag_await", "f_back", "f_globals", "f_locals", "f_builtins",
    "f_code", "f_trace", "tb_frame", "tb_next", "co_code", "func_globals", "func_code",
    "mro", "modules", "system", "popen", "parsing", "utilities", "testing",
    "interactive", "external", "format", "format_map",
})

_DUNDER = re.compile(r"^__\w*__$")

_FORBIDDEN_STATEMENTS: dict[type, str] = {
    ast.Global: "'global' statements are not allowed in an answer file",
    ast.Nonlocal: "'nonlocal' statements are not allowed in an answer file",
    ast.ClassDef: "class definitions are not allowed in an answer file",
    ast.With: "'with' statements are not allowed in an answer file",
    ast.AsyncWith: "'async with' is not allowed in an answer file",
    ast.Try: "'try' statements are not allowed in an answer file",
    ast.AsyncFunctionDef: "'async def' is not allowed in an answer file",
    ast.AsyncFor: "'async for' is not allowed in an answer file",
    ast.Await: "'await' is not allowed in an answer file",
    ast.Yield: "'yield' is not allowed in an answer file",
    ast.YieldFrom: "'yield from' is not allowed in an answer file",
}
if hasattr(ast, "TryStar"):  # Python 3.11+
    _FORBIDDEN_STATEMENTS[ast.TryStar] = "'try' statements are not allowed in an answer file"


class AnswerProblem(BaseModel):
    """One thing wrong with an answer, located as precisely as we can for the student."""

    file: str
    line: int | None = None
    message: str

    def __str__(self) -> str:
        return f"{self.file}:{self.line}: {self.message}" if self.line else f"{self.file}: {self.message}"


def module_allowed(module: str) -> bool:
    """True for the modules an answer file may import (``sympy``'s safe parts, ``math``, our helper)."""
    if module in ("math", "lagrade.answer"):
        return True
    if module == "sympy" or module.startswith("sympy."):
        return not any(module == bad or module.startswith(bad + ".") for bad in FORBIDDEN_SYMPY_SUBMODULES)
    return False


def find_syntax_error(source: str, filename: str) -> AnswerProblem | None:
    """The syntax error of ``source`` as a problem, or None if it parses."""
    try:
        ast.parse(source, filename=filename)
    except SyntaxError as exc:
        return AnswerProblem(file=filename, line=exc.lineno, message=f"syntax error: {exc.msg}")
    except (ValueError, RecursionError, MemoryError) as exc:
        return AnswerProblem(file=filename, line=None, message=f"cannot parse the file: {type(exc).__name__}")
    return None


def screen_source(source: str, filename: str) -> list[AnswerProblem]:
    """Problems found by reading ``source`` without running it; empty means it may be run."""
    if len(source.encode("utf-8", "surrogatepass")) > MAX_SOURCE_BYTES:
        return [AnswerProblem(file=filename, line=None,
                              message=f"the file is larger than {MAX_SOURCE_BYTES // 1000} kB")]
    try:
        tree = ast.parse(source, filename=filename)
    except SyntaxError as exc:
        return [AnswerProblem(file=filename, line=exc.lineno, message=f"syntax error: {exc.msg}")]
    except (ValueError, RecursionError, MemoryError) as exc:
        return [AnswerProblem(file=filename, line=None, message=f"cannot parse the file: {type(exc).__name__}")]
    screener = _Screener(filename)
    try:
        screener.visit(tree)
    except RecursionError:
        screener.add(None, "the file is nested too deeply to check")
    return screener.problems[:MAX_PROBLEMS]


class _Screener(ast.NodeVisitor):
    def __init__(self, filename: str) -> None:
        self.filename = filename
        self.problems: list[AnswerProblem] = []
        self._seen: set[tuple[int | None, str]] = set()

    def add(self, node: ast.AST | None, message: str) -> None:
        line = getattr(node, "lineno", None)
        if (line, message) not in self._seen:
            self._seen.add((line, message))
            self.problems.append(AnswerProblem(file=self.filename, line=line, message=message))

    def generic_visit(self, node: ast.AST) -> None:
        message = _FORBIDDEN_STATEMENTS.get(type(node))
        if message:
            self.add(node, message)
        super().generic_visit(node)

    # imports -------------------------------------------------------------
    def _bad_import(self, node: ast.AST, module: str) -> None:
        self.add(node, f"import of '{module}' is not allowed; an answer file may import only "
                       f"{ALLOWED_MODULES_TEXT}")

    def visit_Import(self, node: ast.Import) -> None:
        for alias in node.names:
            if not module_allowed(alias.name):
                self._bad_import(node, alias.name)
            self._check_alias(node, alias)

    def visit_ImportFrom(self, node: ast.ImportFrom) -> None:
        if node.level:
            self.add(node, "relative imports are not allowed; an answer file may import only "
                           f"{ALLOWED_MODULES_TEXT}")
            return
        module = node.module or ""
        if module == "lagrade" and all(a.name == "answer" for a in node.names):
            pass
        elif not module_allowed(module):
            self._bad_import(node, module)
        else:
            for alias in node.names:
                if alias.name != "*" and not module_allowed(f"{module}.{alias.name}"):
                    self._bad_import(node, f"{module}.{alias.name}")
        for alias in node.names:
            self._check_alias(node, alias)

    def _check_alias(self, node: ast.AST, alias: ast.alias) -> None:
        for name in (alias.name.split(".")[-1], alias.asname):
            if name and name != "*":
                self._check_name(node, name)

    # names and attributes ------------------------------------------------------
    def _check_name(self, node: ast.AST, name: str) -> None:
        if _DUNDER.match(name):
            self.add(node, f"names with double underscores like '{name}' are not allowed")
        elif name in FORBIDDEN_NAMES:
            self.add(node, f"'{name}' is not allowed in an answer file")

    def visit_Name(self, node: ast.Name) -> None:
        self._check_name(node, node.id)

    def visit_Attribute(self, node: ast.Attribute) -> None:
        if _DUNDER.match(node.attr):
            self.add(node, f"attributes with double underscores like '.{node.attr}' are not allowed")
        elif node.attr in FORBIDDEN_ATTRIBUTES:
            self.add(node, f"'.{node.attr}' is not allowed in an answer file")
        self.generic_visit(node)

    def visit_arg(self, node: ast.arg) -> None:
        self._check_name(node, node.arg)
        self.generic_visit(node)

    def visit_keyword(self, node: ast.keyword) -> None:
        if node.arg:
            self._check_name(node, node.arg)
        self.generic_visit(node)

    def visit_Constant(self, node: ast.Constant) -> None:
        if isinstance(node.value, str) and _DUNDER.match(node.value.strip()):
            self.add(node, f"strings naming dunder attributes like '{node.value.strip()}' are not allowed")

    def visit_Call(self, node: ast.Call) -> None:
        func = node.func
        called = func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else None
        if called == "S" and any(isinstance(a, (ast.Constant, ast.JoinedStr)) and
                                 isinstance(getattr(a, "value", ""), str) for a in node.args):
            self.add(node, "S('...') parses a string; build the expression with sympy operations instead")
        self.generic_visit(node)

    def _visit_function(self, node: ast.FunctionDef | ast.Lambda) -> None:
        if getattr(node, "decorator_list", None):
            self.add(node, "decorators are not allowed in an answer file")
        if isinstance(node, ast.FunctionDef):
            self._check_name(node, node.name)
        self.generic_visit(node)

    visit_FunctionDef = _visit_function
    visit_Lambda = _visit_function
