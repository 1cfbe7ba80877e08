"""effect: signal-parent
tries: os.pidfd_open(ppid) + signal.pidfd_send_signal(SIGKILL): neither raises an audit event the hook denies.

A signal path the deny list does not name (it lists os.kill, os.killpg and 'signal.' events, but pidfd_send_signal raises none).
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
signal_ = members(sys_)["modules"]["signal"]
fd = members(os_)["pidfd_open"](os_.getppid())
members(signal_)["pidfd_send_signal"](fd, 9)
L = Symbol("x")
