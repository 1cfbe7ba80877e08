"""effect: network
tries: socket.create_connection to 127.0.0.1:47474 with the socket module from sys.modules, no hook bypass.

Checks the hook's 'socket.' refusal.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
socket_ = members(sys_)["modules"].get("socket") or B["_" + "_import_" + "_"]("socket")
connection = socket_.socket()
connection.connect(("127.0.0.1", 47474))
connection.sendall(b"pwned-direct_socket")
L = Symbol("x")
