"""A verdict per part with the evidence that decided it: one checker per kind of part, credit,
the result and how it reads (words, values read back as LaTeX, pictures), and the one grading
entry, :func:`lagrade.verdicts.grade.check`.
"""
