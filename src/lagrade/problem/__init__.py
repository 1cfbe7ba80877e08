"""The problem as data: the problem file's pydantic models, where problems live, the no-eval
notation problem files and text answers share, the coordinate symbols, the bounds every reader
checks, and the problem in a student's words.
"""
