"""The version, in a module of its own so that lagrade's modules can name it without importing
the package's public API (and through it the grader)."""

__version__ = "0.1.0"
