"""Running a student's ``answer.py`` where it cannot harm: the OS jail, the clean zygote, the child.

``kernel`` is the kernel's barrier, ``zygote`` the process that forks every child without ever
holding a reference, ``child`` what runs in it, ``screen`` the tripwires, ``sandbox`` the grader's
side of a run, and ``rebuild`` turns what a child sends back into sympy objects without ``eval``.
"""
