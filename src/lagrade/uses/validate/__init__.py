"""``lagrade validate``: a problem file proved before a student sees it.

Its schema and domains, its reference graded full marks, its named mistakes told apart, and answers
generated from the reference (right ones in other forms, wrong ones by one slip each) graded by the
same checkers a student's answer reaches (:mod:`lagrade.uses.validate.run`).
"""
