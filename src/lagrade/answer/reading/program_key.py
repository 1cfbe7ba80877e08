"""An answer file as a key that is equal only for the same program, whatever its comments say.

A grader runs a file in the jail once and gives every later file with the same key that run's result
(`lagrade.uses.bulk.worker.Grader`). Students rarely hand in the same bytes: the template's header
comment carries a name, a resubmission adds a remark. What the file does is a function of its
tokens, so an ``answer.py``'s key is its token stream without its comments, each token with its
position (line and column): two files with one key differ only in the text of their comments, in
comment lines after the last line of code and in trailing blanks, so even an answer that reads its
own line numbers runs the same. A text answer (``answer.toml``) is keyed by its text with the lines
that are comments alone emptied, every other line in its place. Anything else (a notebook, a file that does not tokenize or parse, a large one)
is keyed by its bytes.
"""

from __future__ import annotations

import hashlib
import io
import tokenize
import tomllib

#: larger files are keyed by their bytes: keying runs before the file's grading is bounded (in the
#: server's queue, before the next attempt goes to a grader), and a 16 kB file of short tokens takes
#: about 45 ms to tokenize here (64 kB: 185 ms); a template's copy is a few kB
MAX_TOKENIZED = 16 * 1024

_DROPPED = (tokenize.COMMENT, tokenize.NL)
#: tokens that mark where lines, blocks and the file end: placed after the comments that follow the code
_UNPLACED = (tokenize.NEWLINE, tokenize.DEDENT, tokenize.ENDMARKER)


def program_key(suffix: str, data: bytes) -> bytes:
    """A digest equal for two files only when they are the same program (see the module)."""
    if suffix == ".toml" and len(data) <= MAX_TOKENIZED:
        text = _toml_without_comment_lines(data)
        if text is not None:
            return hashlib.sha256(b"toml\0" + text.encode("utf-8", "surrogatepass")).digest()
    if suffix == ".py" and len(data) <= MAX_TOKENIZED:
        try:
            tokens = [(tok.type, tok.string, None if tok.type in _UNPLACED else tok.start)
                      for tok in tokenize.tokenize(io.BytesIO(data).readline) if tok.type not in _DROPPED]
        except (SyntaxError, tokenize.TokenError, UnicodeDecodeError, ValueError):
            pass
        else:
            return hashlib.sha256(b"tokens\0" + repr(tokens).encode("utf-8", "surrogatepass")).digest()
    return hashlib.sha256(b"bytes\0" + data).digest()


def _toml_without_comment_lines(data: bytes) -> str | None:
    """A text answer with every line that is a comment alone emptied to ``#`` and the comment and
    blank lines after its last line of content dropped; None unless it parses to the same table as
    the file (a line that only looked like a comment, inside a multi-line string, changes the
    table). Every other line keeps its number and text: the reader's messages name lines, and look
    for the line of each key (`lagrade.answer.reading.text`), which a comment line never is."""
    try:
        text = data.decode("utf-8")
        table = tomllib.loads(text)
    except (UnicodeDecodeError, tomllib.TOMLDecodeError, RecursionError, ValueError):
        return None
    lines = ["#" if line.lstrip().startswith("#") else line for line in text.split("\n")]
    while lines and lines[-1].strip() in ("", "#"):
        lines.pop()
    stripped = "\n".join(lines)
    try:
        return stripped if tomllib.loads(stripped) == table else None
    except (tomllib.TOMLDecodeError, RecursionError, ValueError):
        return None
