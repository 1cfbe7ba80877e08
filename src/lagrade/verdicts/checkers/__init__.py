"""One checker per kind of part; the grader looks them up here by the part's ``kind``."""

from lagrade.verdicts.checkers.admit import admitted
from lagrade.verdicts.checkers.base import Context, InvalidAnswer
from lagrade.verdicts.checkers.conditions import check_conditions
from lagrade.verdicts.checkers.dynamics import check_eom, check_hamilton_eqs, check_hamiltonian, check_lagrangian
from lagrade.verdicts.checkers.general import for_general_functions
from lagrade.verdicts.checkers.motion import check_conserved, check_trajectory
from lagrade.verdicts.checkers.numerical import check_numerical_solution
from lagrade.verdicts.checkers.reduced import check_reduced
from lagrade.verdicts.checkers.values import (
    check_boolean,
    check_equation_root,
    check_expression,
    check_expression_set,
    check_integer,
    check_names,
)

#: every checker reads through `read_sympy` and accepts only as `admitted` allows (checkers/admit.py)
CHECKERS = {kind: admitted(for_general_functions(checker)) for kind, checker in {
    "lagrangian": check_lagrangian,
    "eom": check_eom,
    "hamiltonian": check_hamiltonian,
    "hamilton_eqs": check_hamilton_eqs,
    "expression": check_expression,
    "expression_set": check_expression_set,
    "equation_root": check_equation_root,
    "boolean": check_boolean,
    "integer": check_integer,
    "names": check_names,
    "conserved": check_conserved,
    "trajectory": check_trajectory,
    "reduced": check_reduced,
    "numerical_solution": check_numerical_solution,
    "conditions": check_conditions,
}.items()}

__all__ = ["CHECKERS", "Context", "InvalidAnswer"]
