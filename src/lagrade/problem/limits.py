"""Every bound on what one answer may cost: read here by the engine, the readers and bulk grading.

Its own module, importing nothing, so that the engine (`lagrade.verdicts.grade`), the assignment file's model
(`lagrade.uses.bulk.assignment`) and the lowest layer (`lagrade.problem.notation`, which every reader of a
student's text or a sandbox child's values builds with) all read the same numbers. The readers check
the *reading* bounds before sympy builds anything (docs/safety.md, "What a reader refuses"): an answer
over one is ``invalid`` with a line naming what was too large and the limit.
"""

#: seconds of CPU to grade the values once the answer file has run (``[limits] grading_seconds``);
#: reading the answer's text or rebuilding its child's values is bounded alike (`lagrade.verdicts.grade.check`)
GRADING_SECONDS = 120.0

# --------------------------------------------------------------------------- reading: any math text
#: characters of one formula's text (or of one value's ``srepr``)
MAX_TEXT_CHARS = 1_000_000
#: syntax nodes of one formula (a shared subexpression counted every time it is used)
MAX_NODES = 300_000
#: levels of nesting of one formula (brackets, or calls, or powers)
MAX_DEPTH = 100
#: the largest integer literal
MAX_INT_ABS = 10**60
#: digits of all integer literals of one formula together
MAX_TOTAL_INT_DIGITS = 200_000
#: digits of any exact number an answer holds (a numerator or a denominator), however it was made: a
#: power (``(3*g*x)**n`` has 3**n in it), a product of powers, a sum of fractions. Far below the 4300
#: digits Python turns an int into text (``sys.get_int_max_str_digits``), so that every stage after
#: the reader (the echo, the feedback, JSON, the gradebook, the preview) prints what the engine makes
#: of a few such numbers multiplied: ``g*9^4999`` (4771 digits) passed a bound of 10 000 and died there
MAX_NUMBER_DIGITS = 1_000
#: the name the power check has always given it
MAX_POWER_DIGITS = MAX_NUMBER_DIGITS
#: the largest exact exponent a power of anything but a plain number may have, nested powers
#: counted by the product of their exponents: ``((x**a)**b)`` is x**(a*b)
MAX_EXPONENT = 1_000
#: terms of any subexpression once multiplied out (what ``sympy.expand``, which the engine calls,
#: would make): ``(a + b + c)**100`` is 5151 terms, ``(a + b)*(c + d)*...`` 2**factors
MAX_EXPANDED_TERMS = 100_000
MAX_NAME_CHARS = 64
MAX_FLOAT_PRECISION = 10_000
MAX_DERIVATIVE_ORDER = 100
#: nodes a derivative taken twice or more may be estimated to reach: an expression of n nodes
#: differentiated k times is taken as n**k (a product's derivative has a term for each factor, each
#: differentiated again): diff(sin(x)*cos(y)*z^3*exp(x*y)*m, t, 40) was minutes of sympy
MAX_DERIVATIVE_TERMS = 100_000

# --------------------------------------------------------------------------- reading: answer.toml
#: bytes of one answer.toml
MAX_TOML_BYTES = 200_000
#: levels of arrays and tables one answer.toml may nest (an answer needs 3: a table of lists of text)
MAX_TOML_DEPTH = 8
#: characters of LaTeX in one answer.toml (sympy's LaTeX parser takes about 2 ms per character)
MAX_LATEX_FILE_CHARS = 8000
#: characters of one LaTeX formula
MAX_LATEX_CHARS = 2000
#: levels of ``{}`` groups of one LaTeX formula, and of the tree its parse is rebuilt from
MAX_BRACE_DEPTH = 40
MAX_REBUILD_DEPTH = 150
