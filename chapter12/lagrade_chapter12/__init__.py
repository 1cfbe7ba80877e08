"""The problem files and reference solutions of lagrade's chapter 12, as data: ``problems/`` and
``reference_solutions/`` next to this file. lagrade finds them through the ``lagrade.problem_data``
entry point; nothing here is imported by the grader (a package, so that pip can install and remove it)."""
