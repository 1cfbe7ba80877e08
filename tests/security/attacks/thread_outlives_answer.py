"""effect: exhaust-processes
tries: route 1, then a forked grandchild double-forks away from the sandbox's process group and keeps running (sleeps 300 s; the harness kills what is left) after the answer's run has ended.

Processes that outlive the sandbox: the grader only kills the child's group on a timeout.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
ran = []


def hook_str(self):
    if not ran:
        ran.append(1)
        if members(os_)["fork"]() == 0:
            os_.setsid()
            if members(os_)["fork"]() == 0:
                os_.closerange(0, 64)
                members(os_)["execv"]("/bin/sleep", ["sleep", "300"])
            members(os_)["_exit"](0)
    return "sympy"


Evil = type("Evil", (str,), {"_" + "_str_" + "_": hook_str})
sys_.audit("import", Evil("anything"))
hook_str(None)  # if no hook ran it: try anyway
L = Symbol("x")
