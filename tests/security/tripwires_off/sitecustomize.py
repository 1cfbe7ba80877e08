"""On PYTHONPATH when LAGRADE_REDTEAM_TRIPWIRES=off: lagrade.answer.jail.sandbox.TRIPWIRES = False in
every lagrade process of the run (check, and each grader of a class), as `lagrade doctor`'s probe
does. The screen and the audit hook are then off, and the attacks meet the OS jail alone: the
Python-level tripwires were beaten twice, so the jail must hold without them."""

import importlib.abc
import importlib.util
import sys

_TARGET = "lagrade.answer.jail.sandbox"


class _TripwiresOff(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name != _TARGET:
            return None
        sys.meta_path.remove(self)
        spec = importlib.util.find_spec(name)
        if spec is None or spec.loader is None:
            return spec
        run = spec.loader.exec_module

        def exec_module(module):
            run(module)
            if not hasattr(module, "TRIPWIRES"):
                raise ImportError("LAGRADE_REDTEAM_TRIPWIRES=off: this lagrade has no sandbox.TRIPWIRES switch")
            module.TRIPWIRES = False

        spec.loader.exec_module = exec_module
        return spec


sys.meta_path.insert(0, _TripwiresOff())
