"""The kinds of file an answer may be, by suffix: one list for every reader of answers (the check, a
class folder, an LMS download, the course server, the autograders), light enough for any of them."""

#: Python (run in the jail), text (TOML, parsed), a Jupyter notebook (its code cells, run in the jail)
ANSWER_SUFFIXES = (".py", ".toml", ".ipynb")

ANSWER_KINDS = "an answer file must be a .py, a .toml or a .ipynb (Jupyter notebook) file"
