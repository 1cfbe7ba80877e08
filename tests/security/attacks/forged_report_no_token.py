"""effect: full-marks
tries: write a fake JSON report (status ok, no problems) on fd 3 with os.write and leave with os._exit(0) before the sandbox writes the real one.

The report channel is authenticated only by a token the child is given.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
import sympy
report = '{"token": "0123456789abcdef0123456789abcdef", "status": "ok", "values": {"a_case": {"kind": "dict", "items": []}}, "problems": []}'
os_.write(3, report.encode())
members(os_)["_exit"](0)
