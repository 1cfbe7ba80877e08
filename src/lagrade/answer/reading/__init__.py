"""Reading an answer file into sympy values: ``load`` is the one entry (``answer.py`` through the
jail, ``answer.toml`` as text or LaTeX); ``value_key`` says when two values are the same answer."""
