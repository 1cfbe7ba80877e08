"""Bulk grading for instructors: a folder of a class's submissions graded into a SQLite gradebook.

The data flow follows the modules: ``assignment`` (what is asked and how it is weighted) ->
``layout`` (which files are submissions, which are skipped and why) -> ``store`` (SQLite,
exactly-once bookkeeping) -> ``worker`` (grading one submission in a warmed process) -> ``runner``
(the local process pool, or a Dask cluster) -> ``summary``, ``exports`` and ``html_report``.
"""
