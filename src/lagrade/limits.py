"""The CPU-time bound on grading one answer's values, shared by a check and bulk grading.

Its own module so that the engine (`lagrade.grade`) and the assignment file's model
(`lagrade.bulk.assignment`) both read it without the engine importing bulk grading.
"""

#: seconds of CPU to grade the values once the answer file has run (``[limits] grading_seconds``)
GRADING_SECONDS = 120.0
