"""Student text made printable before it reaches a terminal: the one boundary every command prints through.

Whatever a student wrote may come back in what lagrade prints: an exception's message, a dict key,
a name in ``answer.toml``, a folder name. Raw, it could carry terminal control sequences (OSC 52 puts
a command in the instructor's clipboard, ``ESC ] 0`` sets the window title, CSI moves the cursor and
paints a fake green "5 / 5" over the real line; C1 controls, carriage returns and backspaces write over
a line) or rich's console markup (``[bold green]5 / 5[/]``). :func:`printable` shows every such
character as a visible escape (``\\x1b``); :func:`plain` hands text to rich as a ``Text``, never read as
markup; :func:`json_printable` escapes in JSON text what JSON encoders leave raw (C1 controls, the
bidirectional overrides), as the same string value. The gradebook and ``--json`` keep the text itself.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from rich.text import Text

#: C0 controls but newline and tab, DEL, C1 controls, the bidirectional controls that reorder what a
#: line shows, line and paragraph separators, and lone surrogates (which no terminal encoding takes)
_UNPRINTABLE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028-\u202e\u2066-\u2069\ud800-\udfff]")
#: what a JSON encoder leaves raw of those (it escapes C0 controls itself, and no surrogate is encoded)
_RAW_IN_JSON = re.compile("[\x7f-\x9f\u061c\u200e\u200f\u2028-\u202e\u2066-\u2069]")


def _visible(match: re.Match) -> str:
    code = ord(match.group())
    return f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}"


def printable(text: object) -> str:
    """``text`` with every control character shown as a visible escape (newlines and tabs kept)."""
    return _UNPRINTABLE.sub(_visible, str(text))


def plain(text: object) -> Text:
    """``text`` for a rich table or console: printable, and a ``Text``, so ``[bold]`` in it is literal."""
    from rich.text import Text

    return Text(printable(text))


def json_printable(text: str) -> str:
    """JSON text with the characters its encoder leaves raw written as ``\\u`` escapes: in JSON text they
    can only be inside strings, where the escape is the same value."""
    return _RAW_IN_JSON.sub(lambda m: f"\\u{ord(m.group()):04x}", text)
