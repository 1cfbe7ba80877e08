"""effect: hang
tries: os.pidfd_open(ppid) + signal.pidfd_send_signal(SIGSTOP): the grader is stopped and never gives a verdict.

Same unaudited signal path, used to hang the grader instead of killing it.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
signal_ = members(sys_)["modules"]["signal"]
members(signal_)["pidfd_send_signal"](members(os_)["pidfd_open"](os_.getppid()), 19)
L = Symbol("x")
